#include "viz/scene.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <nlohmann/json.hpp>

#include "core/geo.h"
#include "core/text.h"
#include "core/units.h"
#include "viz/layout.h"
#include "viz/svg.h"

namespace squawk::viz {

using nlohmann::json;

namespace {

// [lat, lon, hdg, tas] -> Pose.
Pose pose(const json& a, std::string id) {
  return {std::move(id), a.at(0).get<double>(), a.at(1).get<double>(), a.at(2).get<double>(), {}, false};
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

Status check_frame(const Scene& scene, long long frame) {
  const long long n = static_cast<long long>(scene.frames.size());
  if (frame == -1 || (frame >= 0 && frame < n)) return Status::ok();
  return Status::invalid("frame " + std::to_string(frame) + " does not exist: the episode has " +
                              std::to_string(n) + " frames, numbered 0 to " + std::to_string(n - 1) +
                              " (-1: the last)");
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

Box around(Point c, double r) { return {c.x - r, c.y - r, c.x + r, c.y + r}; }

constexpr const char* kOwn = "#000080";
constexpr const char* kOther = "#303030";
constexpr const char* kAlert = "#dc143c";
constexpr const char* kClosest = "#b35900";

// The ownship's closest approach to any intruder over frames 0..last.
struct Closest {
  double nm = std::numeric_limits<double>::infinity();
  size_t frame = 0;
  std::string id;
  Pose own, other;
};

Closest closest_approach(const Scene& scene, size_t last) {
  Closest c;
  for (size_t f = 0; f <= last; ++f) {
    const auto& ac = scene.frames[f].aircraft;
    for (size_t k = 1; k < ac.size(); ++k) {
      const double d = geo::kwikdist_nm(ac[0].lat, ac[0].lon, ac[k].lat, ac[k].lon);
      if (d < c.nm) c = {d, f, ac[k].id, ac[0], ac[k]};
    }
  }
  return c;
}

}  // namespace

std::string render_scene(const Scene& scene, const RenderOptions& opt) {
  const auto& frames = scene.frames;
  const size_t fi = opt.frame < 0 ? frames.size() - 1 : static_cast<size_t>(opt.frame);
  const Frame& now = frames[fi];
  const double size = opt.size_px;
  const double fs = std::clamp(size / 60.0, 8.0, 12.0);         // [px] label font
  const double sym = std::clamp(size / 720.0, 0.6, 1.5);        // [-] symbol scale
  const double fs_title = std::clamp(size / 50.0, 9.0, 14.0);   // [px] caption font
  const double top = fs_title * 1.25 + fs * 1.3 + 12;           // [px] caption band
  const double bottom_band = fs * 2.2 + 12;                     // [px] scale bar and note band
  const double map_top = top, map_bottom = size - bottom_band;

  // Projection around the first frame's first aircraft (the ownship), extent
  // over every track point, the waypoint and the circles of the drawn frame.
  const Pose& ref = frames.front().aircraft.empty() ? Pose{} : frames.front().aircraft.front();
  Projection pr{ref.lat, ref.lon, std::cos(units::deg_to_rad(ref.lat))};
  const double rpz_km = scene.rpz_nm * units::kNm / 1000.0;
  double xlo = 0, xhi = 0, ylo = 0, yhi = 0;
  bool any = false;
  auto grow = [&](double x, double y, double r) {
    if (!any) xlo = xhi = x, ylo = yhi = y, any = true;
    xlo = std::min(xlo, x - r), xhi = std::max(xhi, x + r);
    ylo = std::min(ylo, y - r), yhi = std::max(yhi, y + r);
  };
  for (size_t f = 0; f <= fi; ++f)
    for (const auto& a : frames[f].aircraft) grow(pr.x_km(a.lon), pr.y_km(a.lat), 0);
  for (size_t k = 0; k < now.aircraft.size(); ++k)
    if (scene.ownship ? k > 0 : now.aircraft[k].alert)
      grow(pr.x_km(now.aircraft[k].lon), pr.y_km(now.aircraft[k].lat), rpz_km);
  if (scene.waypoint) grow(pr.x_km(scene.wpt_lon), pr.y_km(scene.wpt_lat), scene.wpt_radius_km);
  const double margin = std::min(3.5 * fs + 14, 0.08 * size);  // [px] room for labels at the map's edge
  const double w_px = size - 2 * margin, h_px = map_bottom - map_top - 2 * margin;
  const double span_x = std::max(xhi - xlo, 1.0), span_y = std::max(yhi - ylo, 1.0);
  const double scale = std::min(w_px / span_x, h_px / span_y);  // [px/km]
  const double cx = (xlo + xhi) / 2, cy = (ylo + yhi) / 2;
  auto P = [&](double lat, double lon) {
    return Point{size / 2 + (pr.x_km(lon) - cx) * scale, (map_top + map_bottom) / 2 - (pr.y_km(lat) - cy) * scale};
  };

  Svg svg(size, size, "#87ceeb");
  LabelLayout labels({2, map_top + 2, size - 2, map_bottom - 2});
  // Tracks.
  for (size_t k = 0; k < now.aircraft.size(); ++k) {
    std::vector<Point> track;
    for (size_t f = 0; f <= fi; ++f)
      for (const auto& a : frames[f].aircraft)
        if (a.id == now.aircraft[k].id) track.push_back(P(a.lat, a.lon));
    const bool own = scene.ownship && k == 0;
    svg.polyline(track, own ? kOwn : "#505050", own ? 2.0 : 1.2, own ? "" : "5,4");
  }
  // Waypoint: concentric circles (its label is placed with the others).
  const Point w = P(scene.wpt_lat, scene.wpt_lon);
  if (scene.waypoint) {
    svg.circle(w, scene.wpt_radius_km * scale, "white", "none", 2);
    svg.circle(w, 5, "white", "white");
    labels.block(around(w, std::max(6.0, scene.wpt_radius_km * scale) + 2));
  }
  // Start of the ownship's track.
  const Point s0 = P(ref.lat, ref.lon);
  if (scene.ownship) {
    svg.rect({s0.x - 4, s0.y - 4}, 8, 8, "none", kOwn, 1.5);
    labels.block(around(s0, 6));
  }
  // Symbols first, so that every label can avoid every symbol.
  // Symbols and the square inside each separation circle are kept free of labels.
  for (size_t k = 0; k < now.aircraft.size(); ++k) {
    const Pose& a = now.aircraft[k];
    const bool ringed = scene.ownship ? k > 0 : a.alert;
    labels.block(around(P(a.lat, a.lon), std::max(sym * (scene.ownship && k == 0 ? 13.0 : 9.0),
                                                  ringed ? rpz_km * scale * 0.7 : 0.0)));
  }
  // Closest approach of the ownship to any intruder so far.
  Closest ca;
  if (scene.ownship && fi > 0) ca = closest_approach(scene, fi);
  if (std::isfinite(ca.nm)) {
    const Point a = P(ca.own.lat, ca.own.lon), b = P(ca.other.lat, ca.other.lon);
    svg.line(a, b, kClosest, 2, "3,3");
    svg.circle(a, 3.5, kClosest, kClosest);
    svg.circle(b, 3.5, kClosest, kClosest);
    labels.block(around(a, 4));
    labels.block(around(b, 4));
  }
  struct Label {
    Point anchor;
    std::string line1, line2;
    std::string colour;
    double gap;
    bool bold;
  };
  std::vector<Label> todo;
  const double wpt_px = std::max(6.0, scene.wpt_radius_km * scale);
  if (scene.waypoint) todo.push_back({w, "waypoint", "", "white", wpt_px + 5, true});
  // Aircraft: intruders (or traffic) with separation circles, the ownship last drawn on top.
  const Pose* own = scene.ownship && !now.aircraft.empty() ? &now.aircraft.front() : nullptr;
  for (size_t k = own ? 1 : 0; k < now.aircraft.size(); ++k) {
    const Pose& a = now.aircraft[k];
    const Point c = P(a.lat, a.lon);
    const bool intrusion = own && geo::kwikdist_nm(own->lat, own->lon, a.lat, a.lon) < scene.rpz_nm;
    const std::string col = (intrusion || a.alert) ? kAlert : kOther;
    if (own || a.alert) svg.circle(c, rpz_km * scale, col, "none", 1.5);
    svg.polygon(needle(c, a.hdg, 9 * sym, 5 * sym), col);
    todo.push_back({c, a.id, a.info, col, (own || a.alert) ? std::max(10.0, rpz_km * scale + 3) : 10, true});
  }
  if (own) {
    const Point o = P(own->lat, own->lon);
    svg.polygon(needle(o, own->hdg, 13 * sym, 7 * sym), kOwn);
    todo.insert(todo.begin(), {o, own->id, own->info, kOwn, 15, true});
    todo.push_back({s0, "start", "", kOwn, 9, false});
  }
  if (std::isfinite(ca.nm)) {
    const Point a = P(ca.own.lat, ca.own.lon), b = P(ca.other.lat, ca.other.lon);
    todo.push_back({{(a.x + b.x) / 2, (a.y + b.y) / 2},
                    "closest " + text::fmt_double(ca.nm, 1) + " NM",
                    "to " + ca.id + ", t = " + text::fmt_double(frames[ca.frame].t, 0) + " s", kClosest, 6, false});
  }
  for (const auto& l : todo) {
    const double h = l.line2.empty() ? fs * 1.2 : fs * 2.3;
    const double wl = std::max(text_width(l.line1, fs, l.bold), text_width(l.line2, fs * 0.9));
    // Dense traffic: a label with no free place is left out rather than piled up.
    const auto placed = labels.place(l.anchor, wl, h, l.gap, scene.ownship);
    if (!placed) continue;
    const Point at = *placed;
    svg.text({at.x, at.y + fs}, l.line1, fs, "start", l.colour, 0, l.bold);
    if (!l.line2.empty()) svg.text({at.x, at.y + fs * 2.15}, l.line2, fs * 0.9, "start", l.colour);
  }

  // Caption band: title, then time / circles / frame; north arrow at the right.
  svg.rect({0, 0}, size, top, "white");
  svg.line({0, top}, {size, top}, "#404040", 1);
  const double arrow_w = 28;
  std::string title = scene.title.empty() ? "episode" : scene.title;
  const double tfs = fit_text(title, size - 20 - arrow_w, fs_title, 7);
  svg.text({10, 6 + tfs}, title, tfs, "start", "black", 0, true);
  // SVG collapses runs of spaces, so the parts are joined by " \u00b7 ".
  std::string line2 = "t = " + text::fmt_double(now.t, 0) + " s \u00b7 frame " + std::to_string(fi) + "/" +
                      std::to_string(frames.size() - 1);
  if (scene.ownship) line2 += " \u00b7 circles: " + text::fmt_double(scene.rpz_nm, 1) + " NM separation";
  if (!scene.subtitle.empty()) line2 += " \u00b7 " + scene.subtitle;
  const double sfs = fit_text(line2, size - 20 - arrow_w, fs, 7);
  svg.text({10, top - 8}, line2, sfs, "start", "#202020");
  const double ax = size - arrow_w / 2 - 4;
  svg.line({ax, top - 6 - fs}, {ax, 12}, "black", 2);
  svg.polygon({{ax, 4}, {ax - 5, 14}, {ax + 5, 14}}, "black");
  svg.text({ax, top - 5}, "N", fs, "middle", "black", 0, true);

  // Bottom band: scale bar at the left, the frame's note beside it.
  svg.rect({0, map_bottom}, size, size - map_bottom, "white");
  svg.line({0, map_bottom}, {size, map_bottom}, "#404040", 1);
  // The scale bar: the largest 1-2-5 length [km] within a third of the view.
  const double third = std::min(w_px, h_px) / scale / 3;
  const double mag = std::pow(10.0, std::floor(std::log10(third)));
  const double bar_km = third >= 5 * mag ? 5 * mag : third >= 2 * mag ? 2 * mag : mag;
  const double y = size - 8, bar = bar_km * scale;
  svg.line({12, y}, {12 + bar, y}, "black", 3);
  svg.line({12, y - 5}, {12, y + 2}, "black", 2);
  svg.line({12 + bar, y - 5}, {12 + bar, y + 2}, "black", 2);
  svg.text({12 + bar / 2, y - 6}, text::fmt_double(bar_km, 1) + " km", fs, "middle");
  if (!now.note.empty()) {
    std::string note = "\u201c" + now.note + "\u201d";
    const double x = 24 + std::max(bar, text_width("000 km", fs));
    const double nfs = fit_text(note, size - x - 10, fs, 7);
    svg.text({x, size - 10}, note, nfs, "start", "black");
  }
  return svg.str();
}

}  // namespace squawk::viz
