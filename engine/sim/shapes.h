// Named areas (BlueSky's areafilter shapes: BOX, CIRCLE, POLY/POLYALT, LINE),
// the regions AREA deletes aircraft outside of.
//
// Contract: coordinates are degrees, altitudes metres, the circle radius
// nautical miles (as BlueSky's CIRCLE takes it). contains() is BlueSky's
// checkInside: a box is inclusive on every side; a circle compares BlueSky's
// flat-earth kwikdist with the radius; a polygon tests the point (lat, lon)
// against its border (even-odd rule); every shape but a line also needs
// bottom <= alt <= top. A line contains nothing (it is drawn only).
#pragma once

#include <map>
#include <string>
#include <vector>

#include "core/status.h"

namespace squawk::sim {

struct Shape {
  enum class Kind { kBox, kCircle, kPoly, kLine };
  Kind kind = Kind::kBox;
  std::vector<double> coords;  // box: lat0 lon0 lat1 lon1; circle: lat lon radius_nm; poly/line: lat lon ...
  double top = 1e9;            // [m]
  double bottom = -1e9;        // [m]

  bool contains(double lat, double lon, double alt) const;
  static const char* kind_name(Kind k);  // "BOX", "CIRCLE", "POLY", "LINE"
};

class ShapeSet {
 public:
  // Defines (or replaces) `name`. Errors name the shape and the bad value: a
  // coordinate outside [-90, 90] / [-180, 180] or not finite, a radius not
  // > 0, too few points (a polygon needs 3, a line 2), a NaN altitude. A top
  // below the bottom is swapped (BlueSky orders them).
  Status define(const std::string& name, Shape shape);
  // Removes `name`; false when there is none.
  bool remove(const std::string& name);
  const Shape* find(const std::string& name) const;
  const std::map<std::string, Shape>& all() const { return shapes_; }
  void clear() { shapes_.clear(); }
  // Appends a deterministic byte image (for Simulation::snapshot).
  void put(std::string& out) const;

 private:
  std::map<std::string, Shape> shapes_;
};

}  // namespace squawk::sim
