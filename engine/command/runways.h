// RunwayDb: runway thresholds from X-Plane's apt.dat, as BlueSky reads them
// (navdatabase/loadnavdata_txt.py, loadthresholds_txt).
//
// apt.dat rows used (whitespace separated):
//   1 / 16 / 17   land airport / seaplane base / heliport header; field 4 is
//                 the ICAO code. Rows after it belong to it.
//   100           land runway: field 2 surface (1 asphalt, 2 concrete; other
//                 surfaces are skipped, as BlueSky does), then one block per
//                 end: fields 8-11 and 17-20 = name, lat [deg], lon [deg],
//                 displaced-threshold length [m].
// A threshold is its end moved along the runway's great-circle bearing (toward
// the other end) by the displaced length; its bearing is that bearing [deg,
// 0-360). Every other row is ignored. Errors name the file and line.
#pragma once

#include <functional>
#include <memory>
#include <string>
#include <string_view>
#include <unordered_map>

#include "core/status.h"

namespace squawk::command {

struct Threshold {
  double lat = 0.0;          // [deg]
  double lon = 0.0;          // [deg]
  double bearing_deg = 0.0;  // runway heading (true) [deg]
};

class RunwayDb {
 public:
  // `apt_dat`: the file's text; `where` names it in errors. Any bytes give a
  // database or an error, never a crash (fuzz_navdb).
  static Result<std::shared_ptr<const RunwayDb>> parse(std::string_view apt_dat, const std::string& where);
  // Reads `dir/apt.dat`, else member apt.dat of `dir/apt.zip` (BlueSky's
  // layout); kNotFound when neither file exists.
  static Result<std::shared_ptr<const RunwayDb>> load(const std::string& dir);

  // `runway` as written after "RW": "06", "Y06", "18L" (leading Ys dropped as
  // BlueSky does; a single digit is padded, "6" = "06"). Error names what is
  // missing and lists the airport's runways.
  Result<Threshold> find(std::string_view airport, std::string_view runway) const;
  size_t airport_count() const { return airports_.size(); }

 private:
  class Reader;
  using Sink = std::function<Status(std::string_view chunk)>;
  // A database from the text `source` hands to its sink in chunks.
  static Result<std::shared_ptr<const RunwayDb>> read(const std::string& where,
                                                      const std::function<Status(const Sink&)>& source);
  std::string where_;
  std::unordered_map<std::string, std::unordered_map<std::string, Threshold>> airports_;
};

}  // namespace squawk::command
