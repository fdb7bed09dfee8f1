#include "viz/scene.h"

#include <algorithm>
#include <cmath>

#include <nlohmann/json.hpp>

#include "core/geo.h"
#include "core/text.h"
#include "core/units.h"
#include "viz/chart.h"
#include "viz/svg.h"

namespace squawk::viz {

using nlohmann::json;

namespace {

// [lat, lon, hdg, tas] -> Pose.
Pose pose(const json& a, std::string id) {
  return {std::move(id), a.at(0).get<double>(), a.at(1).get<double>(), a.at(2).get<double>()};
}

Frame frame_of(const json& j) {
  Frame f;
  f.t = j.at("t").get<double>();
  f.note = j.value("note", "");
  f.aircraft.push_back(pose(j.at("own"), "KL001"));
  const json& in = j.at("intruders");
  for (size_t i = 0; i < in.size(); ++i) f.aircraft.push_back(pose(in[i], std::to_string(i)));
  return f;
}

}  // namespace

Result<Scene> parse_episode_jsonl(const std::string& text, long long episode) {
  Scene s;
  bool found = false;
  size_t line_no = 0;
  for (const auto& raw : text::split(text, '\n')) {
    ++line_no;
    if (text::trim(raw).empty()) continue;
    const std::string where = "episode line " + std::to_string(line_no);
    json j = json::parse(raw, nullptr, false);
    if (j.is_discarded() || !j.is_object()) return Status::corruption(where + ": not a JSON object");
    try {
      const std::string event = j.at("event").get<std::string>();
      const long long k = j.at("episode").get<long long>();
      if (episode < 0 && event == "reset" && !found) episode = k;
      if (k != episode) continue;
      if (event == "reset") {
        s.title = "episode " + std::to_string(k) + " (" + j.value("rules", "") + " rules)";
        s.wpt_lat = j.at("waypoint").at(0).get<double>();
        s.wpt_lon = j.at("waypoint").at(1).get<double>();
        s.frames.push_back(frame_of(j));
        found = true;
      } else if (event == "step") {
        if (!found) return Status::corruption(where + ": a step of episode " + std::to_string(k) + " before its reset");
        s.frames.push_back(frame_of(j));
      }
    } catch (const json::exception& e) {
      return Status::corruption(where + ": expected a recorder event (reset, step or end): " + e.what());
    }
  }
  if (!found)
    return Status::not_found(episode < 0 ? std::string("the recording holds no episode")
                                         : "the recording holds no episode " + std::to_string(episode));
  return s;
}

namespace {

// Local flat projection [km] around a reference point, north up.
struct Projection {
  double lat0, lon0, coslat0;
  double km_per_deg = units::kREarth / 1000.0 * units::kDeg;
  double x_km(double lon) const { return (lon - lon0) * coslat0 * km_per_deg; }
  double y_km(double lat) const { return (lat - lat0) * km_per_deg; }
};

std::vector<Point> needle(Point c, double hdg_deg, double len, double half_width) {
  const double a = units::deg_to_rad(hdg_deg);
  const double fx = std::sin(a), fy = -std::cos(a);  // screen forward (y down)
  const double rx = -fy, ry = fx;
  return {{c.x + fx * len, c.y + fy * len},
          {c.x - fx * len * 0.5 + rx * half_width, c.y - fy * len * 0.5 + ry * half_width},
          {c.x - fx * len * 0.2, c.y - fy * len * 0.2},
          {c.x - fx * len * 0.5 - rx * half_width, c.y - fy * len * 0.5 - ry * half_width}};
}

}  // namespace

std::string render_scene(const Scene& scene, const RenderOptions& opt) {
  const auto& frames = scene.frames;
  const size_t fi = (opt.frame < 0 || static_cast<size_t>(opt.frame) >= frames.size())
                        ? frames.size() - 1
                        : static_cast<size_t>(opt.frame);
  const Frame& now = frames[fi];
  const Pose& own0 = frames.front().aircraft.front();
  Projection pr{own0.lat, own0.lon, std::cos(units::deg_to_rad(own0.lat))};
  const double rpz_km = scene.rpz_nm * units::kNm / 1000.0;

  // Extent: every track point, the waypoint and the circles around the drawn frame.
  double xlo = 0, xhi = 0, ylo = 0, yhi = 0;
  auto grow = [&](double x, double y, double r) {
    xlo = std::min(xlo, x - r), xhi = std::max(xhi, x + r);
    ylo = std::min(ylo, y - r), yhi = std::max(yhi, y + r);
  };
  for (const auto& f : frames)
    for (const auto& a : f.aircraft) grow(pr.x_km(a.lon), pr.y_km(a.lat), 0);
  for (const auto& a : now.aircraft) grow(pr.x_km(a.lon), pr.y_km(a.lat), rpz_km);
  grow(pr.x_km(scene.wpt_lon), pr.y_km(scene.wpt_lat), scene.wpt_radius_km);
  const double span = std::max(xhi - xlo, yhi - ylo) * 1.08 + 1.0;
  const double cx = (xlo + xhi) / 2, cy = (ylo + yhi) / 2;
  const double size = opt.size_px, top_band = 34, scale = (size - top_band - 10) / span;
  auto P = [&](double lat, double lon) {
    return Point{size / 2 + (pr.x_km(lon) - cx) * scale,
                 top_band + (size - top_band) / 2 - (pr.y_km(lat) - cy) * scale};
  };

  Svg svg(size, size, "#87ceeb");
  // Tracks.
  for (size_t k = 0; k < now.aircraft.size(); ++k) {
    std::vector<Point> track;
    for (size_t f = 0; f <= fi; ++f)
      for (const auto& a : frames[f].aircraft)
        if (a.id == now.aircraft[k].id) track.push_back(P(a.lat, a.lon));
    svg.polyline(track, k == 0 ? "#000080" : "#505050", k == 0 ? 2.0 : 1.2, k == 0 ? "" : "5,4");
  }
  // Waypoint: concentric circles.
  const Point w = P(scene.wpt_lat, scene.wpt_lon);
  svg.circle(w, scene.wpt_radius_km * scale, "white", "none", 2);
  svg.circle(w, 5, "white", "white");
  svg.text({w.x + 10, w.y - 8}, "waypoint", 12, "start", "white", 0, true);
  // Intruders with their separation circles; red when the ownship is inside.
  const Pose& own = now.aircraft.front();
  for (size_t k = 1; k < now.aircraft.size(); ++k) {
    const Pose& a = now.aircraft[k];
    const Point c = P(a.lat, a.lon);
    const bool intrusion = geo::kwikdist_nm(own.lat, own.lon, a.lat, a.lon) < scene.rpz_nm;
    const std::string col = intrusion ? "#dc143c" : "#303030";
    svg.circle(c, rpz_km * scale, col, "none", 1.5);
    svg.polygon(needle(c, a.hdg, 9, 5), col);
    const double off = rpz_km * scale * 0.72 + 2;  // label just outside the circle
    svg.text({c.x + off, c.y - off}, a.id, 12, "start", col, 0, true);
  }
  // Ownship start and needle.
  const Point s0 = P(own0.lat, own0.lon);
  svg.rect({s0.x - 4, s0.y - 4}, 8, 8, "none", "#000080", 1.5);
  svg.text({s0.x + 8, s0.y + 4}, "start", 11, "start", "#000080");
  const Point o = P(own.lat, own.lon);
  svg.polygon(needle(o, own.hdg, 13, 7), "#000080");
  svg.text({o.x + 10, o.y + 16}, own.id, 12, "start", "#000080", 0, true);

  // North arrow (top right) and scale bar (bottom left).
  svg.line({size - 30, 78}, {size - 30, 48}, "black", 2);
  svg.polygon({{size - 30, 42}, {size - 36, 54}, {size - 24, 54}}, "black");
  svg.text({size - 30, 94}, "N", 13, "middle", "black", 0, true);
  const auto ticks = nice_ticks(0, span / 4, 2);  // a round length, at most a quarter of the view
  const double bar_km = ticks.size() > 1 ? ticks[1] : span / 4;
  const double y = size - 22;
  svg.line({20, y}, {20 + bar_km * scale, y}, "black", 3);
  svg.line({20, y - 6}, {20, y + 6}, "black", 2);
  svg.line({20 + bar_km * scale, y - 6}, {20 + bar_km * scale, y + 6}, "black", 2);
  svg.text({20 + bar_km * scale / 2, y - 8}, text::fmt_double(bar_km, 1) + " km", 12, "middle");

  // Title band.
  svg.rect({0, 0}, size, top_band, "white");
  std::string caption = scene.title.empty() ? "episode" : scene.title;
  caption += "   t = " + text::fmt_double(now.t, 0) + " s   circles: " + text::fmt_double(scene.rpz_nm, 1) +
             " NM separation";
  svg.text({10, 22}, caption, 13, "start", "black", 0, true);
  if (!now.note.empty()) svg.text({10, size - 54}, now.note, 12, "start", "black");
  return svg.str();
}

}  // namespace squawk::viz
