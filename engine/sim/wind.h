// Wind field (BlueSky's WIND command and windfield, facts from BlueSky
// traffic/windfield.py and windsim.py at 22fdf9e).
//
// Contract:
// - Points carry a wind profile on a fixed altitude axis 0..45 000 ft in
//   100 ft steps: one direction/speed for all altitudes, or samples at given
//   altitudes, linearly interpolated and held constant beyond the first and
//   last sample. Direction is where the wind blows FROM [deg], speed [m/s].
// - dim(): 0 no wind, 1 one point without a profile (constant: its sea-level
//   value everywhere), 2 several points without profiles (inverse squared
//   distance weighting in degrees, longitude scaled by the cosine of the mean
//   latitude, the sea-level values), 3 any profile (the same weighting, then
//   linear interpolation between the two axis altitudes around alt).
// - at() returns the north/east wind components [m/s].
// - Every mutator validates first and leaves the field unchanged on error.
#pragma once

#include <string>
#include <vector>

#include "core/status.h"
#include "core/units.h"

namespace squawk::sim {

constexpr double kWindMinAlt = 50.0 * units::kFt;  // [m] wind acts above this altitude

struct WindSample {
  double alt;      // [m]
  double dir_deg;  // [deg] direction the wind comes from
  double spd;      // [m/s]
};

struct WindNE {
  double north = 0.0;  // [m/s]
  double east = 0.0;   // [m/s]
};

class WindField {
 public:
  // Adds a point with one direction and speed at every altitude.
  Status add_uniform(double lat, double lon, double dir_deg, double spd);
  // Adds a point with samples at increasing altitudes (at least one).
  Status add_profile(double lat, double lon, const std::vector<WindSample>& samples);
  void clear();
  int dim() const { return dim_; }
  int points() const { return static_cast<int>(lat_.size()); }
  WindNE at(double lat, double lon, double alt) const;
  void serialize(std::string& out) const;

 private:
  void push(double lat, double lon, std::vector<double> vn, std::vector<double> ve, bool profile);
  std::vector<double> lat_, lon_;
  std::vector<std::vector<double>> vn_, ve_;  // per point, per axis altitude [m/s]
  int dim_ = 0;
};

}  // namespace squawk::sim
