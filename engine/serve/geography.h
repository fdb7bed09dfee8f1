// Geography for the radar scope: BlueSky's coastlines and FIR borders.
//
// Files (in a BlueSky navdata folder):
//   coastlines.dat  one point a line, "M lat lon" starts a polyline and
//                   "D lat lon" continues it [deg]; other lines are ignored;
//   fir/NAME.txt    one point a line, "N050.46.00.000 E006.05.00.000"
//                   (hemisphere, degrees.minutes.seconds.milliseconds); the
//                   file's points in order are the border of FIR NAME.
// Geography::parse* never fail on odd bytes: a line that is not a point is
// skipped (load() names a file it cannot read).
//
// in_box(box, step) is GET /api/geo's body: {coast: [[lat, lon, lat, lon,
// ...], ...], fir: [{name, pts: [lat, lon, ...]}], truncated}: the polylines
// whose bounding box meets `box`, each point at least `step` degrees (max
// norm) from the one kept before it (ends kept), at most max_points points
// in all (truncated: true when more met the box).
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

#include "core/status.h"
#include "serve/state_json.h"

namespace squawk::serve {

struct Polyline {
  std::string name;           // FIR name ("" for coastlines)
  std::vector<float> pts;     // lat, lon, lat, lon, ... [deg]
  float south = 90, north = -90, west = 180, east = -180;  // bounding box [deg]
};

class Geography {
 public:
  // Reads `dir`/coastlines.dat and `dir`/fir/*.txt; a missing file or folder
  // gives no lines of that kind. Error: a file exists but cannot be read.
  static Result<Geography> load(const std::string& dir);
  static std::vector<Polyline> parse_coastlines(std::string_view text);
  // Degrees of one "N050.46.00.000"-style coordinate, or NaN.
  static double parse_dms(std::string_view token);
  static Polyline parse_fir(std::string_view text, std::string name);

  nlohmann::json in_box(const GeoBox& box, double step_deg, size_t max_points = 200000) const;
  const std::vector<Polyline>& coast() const { return coast_; }
  const std::vector<Polyline>& fir() const { return fir_; }

 private:
  std::vector<Polyline> coast_, fir_;
};

}  // namespace squawk::serve
