#include "sim/shapes.h"

#include <algorithm>
#include <cmath>

#include "core/geo.h"
#include "core/text.h"
#include "sim/byte_image.h"

namespace squawk::sim {

namespace {

bool in_polygon(const std::vector<double>& c, double lat, double lon) {
  bool inside = false;
  const size_t n = c.size() / 2;
  for (size_t i = 0, j = n - 1; i < n; j = i++) {
    const double yi = c[2 * i], xi = c[2 * i + 1], yj = c[2 * j], xj = c[2 * j + 1];
    if ((yi > lat) != (yj > lat) && lon < (xj - xi) * (lat - yi) / (yj - yi) + xi) inside = !inside;
  }
  return inside;
}

Status bad(const std::string& name, const std::string& what) {
  return Status::invalid("shape " + text::quoted(name) + ": " + what);
}

}  // namespace

const char* Shape::kind_name(Kind k) {
  switch (k) {
    case Kind::kBox: return "BOX";
    case Kind::kCircle: return "CIRCLE";
    case Kind::kPoly: return "POLY";
    case Kind::kLine: return "LINE";
  }
  return "?";
}

bool Shape::contains(double lat, double lon, double alt) const {
  if (kind == Kind::kLine || !(alt >= bottom && alt <= top)) return false;
  switch (kind) {
    case Kind::kBox:
      return lat >= std::min(coords[0], coords[2]) && lat <= std::max(coords[0], coords[2]) &&
             lon >= std::min(coords[1], coords[3]) && lon <= std::max(coords[1], coords[3]);
    case Kind::kCircle: return geo::kwikdist_nm(coords[0], coords[1], lat, lon) <= coords[2];
    case Kind::kPoly: return in_polygon(coords, lat, lon);
    case Kind::kLine: return false;
  }
  return false;
}

Status ShapeSet::define(const std::string& name, Shape shape) {
  if (name.empty()) return Status::invalid("shape: the name is empty");
  const auto& c = shape.coords;
  const size_t points = shape.kind == Shape::Kind::kCircle ? 1 : c.size() / 2;
  for (size_t p = 0; p < points; ++p) {
    const double lat = c[2 * p], lon = c[2 * p + 1];
    if (!std::isfinite(lat) || lat < -90 || lat > 90)
      return bad(name, "latitude " + text::fmt_double(lat, 6) + " is not in [-90, 90] deg");
    if (!std::isfinite(lon) || lon < -180 || lon > 180)
      return bad(name, "longitude " + text::fmt_double(lon, 6) + " is not in [-180, 180] deg");
  }
  switch (shape.kind) {
    case Shape::Kind::kBox:
      if (c.size() != 4) return bad(name, "a box needs lat,lon,lat,lon");
      break;
    case Shape::Kind::kCircle:
      if (c.size() != 3) return bad(name, "a circle needs lat,lon,radius");
      if (!(c[2] > 0) || !std::isfinite(c[2]))
        return bad(name, "radius " + text::fmt_double(c[2], 6) + " NM must be > 0");
      break;
    case Shape::Kind::kPoly:
      if (c.size() < 6 || c.size() % 2) return bad(name, "a polygon needs at least 3 lat,lon points");
      break;
    case Shape::Kind::kLine:
      if (c.size() < 4 || c.size() % 2) return bad(name, "a line needs at least 2 lat,lon points");
      break;
  }
  if (std::isnan(shape.top) || std::isnan(shape.bottom)) return bad(name, "top or bottom altitude is NaN");
  if (shape.top < shape.bottom) std::swap(shape.top, shape.bottom);  // as BlueSky orders them
  shapes_[name] = std::move(shape);
  return Status::ok();
}

bool ShapeSet::remove(const std::string& name) { return shapes_.erase(name) > 0; }

const Shape* ShapeSet::find(const std::string& name) const {
  auto it = shapes_.find(name);
  return it == shapes_.end() ? nullptr : &it->second;
}

void ShapeSet::put(std::string& out) const {
  bytes::put<int64_t>(out, static_cast<int64_t>(shapes_.size()));
  for (const auto& [name, s] : shapes_) {
    bytes::put_str(out, name);
    bytes::put<int32_t>(out, static_cast<int32_t>(s.kind));
    bytes::put_vec(out, s.coords);
    bytes::put(out, s.top), bytes::put(out, s.bottom);
  }
}

}  // namespace squawk::sim
