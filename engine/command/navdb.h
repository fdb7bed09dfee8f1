// NavDb: BlueSky's navigation database (airports, fixes, navaids), read-only.
//
// Files (in one folder, as BlueSky ships them in resources/navdata):
//   airports.dat  "code, name, lat, lon, class, maxrunway, country, elevation"
//                 comma separated, '#' comments
//   nav.dat       X-Plane 810 navaids: "type lat lon elev freq range var id desc";
//                 types 2 NDB, 3 VOR, 12 DME, 13 TACAN are kept
//   fix.dat       X-Plane 600 fixes: "lat lon id"
// Names are upper case. Several navaids/fixes may share a name: lookups take
// the one nearest a reference position (flat-earth distance), as BlueSky does.
// Runway thresholds ("EHAM/RW18L") come from apt.dat or apt.zip in the same
// folder (runways.h), read on first use.
#pragma once

#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

#include "command/runways.h"
#include "core/status.h"

namespace squawk::command {

struct NavPoint {
  std::string id;    // upper case
  std::string type;  // "APT", "FIX", "VOR", "NDB", "DME", "TACAN"
  double lat = 0.0;  // [deg]
  double lon = 0.0;  // [deg]
};

class NavDb {
 public:
  // Reads the three files from `dir`. Errors name the file and line.
  static Result<std::shared_ptr<const NavDb>> load(const std::string& dir);
  // The three files' contents; `where` names them in errors (load passes the
  // folder). Any bytes give a database or an error, never a crash.
  static Result<std::shared_ptr<const NavDb>> parse(std::string_view airports_dat, std::string_view nav_dat,
                                                    std::string_view fix_dat, const std::string& where);
  // As load(), but each folder is read once per process (thread-safe); later
  // calls share the same database.
  static Result<std::shared_ptr<const NavDb>> load_cached(const std::string& dir);
  // Builds a database from lists (tests, or callers with their own data).
  NavDb(std::vector<NavPoint> airports, std::vector<NavPoint> waypoints,
        std::shared_ptr<const RunwayDb> runways = nullptr);

  const NavPoint* airport(std::string_view id) const;
  // Airports whose name is `name`, or `name` and a generic word ("Airport",
  // "International"), case and punctuation ignored ("schiphol" -> EHAM).
  std::vector<const NavPoint*> airports_named(std::string_view name) const;
  // Large airports (airports.dat's class) whose name starts with the words of `city` and goes on
  // ("Frankfurt" -> EDDF "FRANKFURT MAIN", not the medium EDFH "FRANKFURT HAHN"); the words before
  // CITY name no city ("Panama" is not KPFN "PANAMA CITY BAY CO INTL").
  std::vector<const NavPoint*> airports_of_city(std::string_view city) const;
  // Airports whose name holds the words of `words` as a run of whole words, the name's other words
  // around them ("Midway" -> KMDW "CHICAGO MIDWAY INTL", "Kennedy" -> KJFK "JOHN F KENNEDY INTL",
  // "Love Field" -> KDAL "DALLAS LOVE FLD" and KPRC "ERNEST A LOVE FLD"), case and punctuation
  // ignored; none for words that only say what kind of field it is ("International", "County
  // Regional").
  std::vector<const NavPoint*> airports_with_words(std::string_view words) const;
  // The large airports, else the medium ones, within kBesideNavaidNm of a navaid called `name`
  // (navaids_named's names, anywhere): the airport of a city people name by its city where the
  // navdata names the airport otherwise ("Toulouse" -> LFBO "BLAGNAC", beside the TOULOUSE VOR).
  // Beside a large one, the other large airports within kCityNm of the navaid come too: a city
  // of several ("London": EGLL beside the LONDON VOR, EGKK, EGLC) is no one airport.
  std::vector<const NavPoint*> airports_beside_navaids(std::string_view name) const;
  static constexpr double kBesideNavaidNm = 10.0;
  static constexpr double kCityNm = 30.0;
  // airports.dat's class of airport `id`, upper case ("LARGE", "MEDIUM", "SMALL"), or "" when
  // unknown.
  std::string airport_class(std::string_view id) const;
  // The navaids whose name, less its kind ("SAN FRANCISCO" of nav.dat's "SAN FRANCISCO
  // VOR-DME"), is `name` (case and punctuation ignored), within `within_nm` of (ref_lat,
  // ref_lon) [deg], nearest first, each ident once (its nearest); of the NavPoint types in
  // `types` ("VOR TACAN", space-separated) only, when it is not empty. Pointers into this NavDb.
  // With `run` true, the navaids whose name holds the words of `name` as a run of whole words
  // ("rockford": RFD "CHICAGO/ROCKFORD").
  std::vector<const NavPoint*> navaids_named(std::string_view name, double ref_lat, double ref_lon,
                                             double within_nm, std::string_view types = {},
                                             bool run = false) const;
  // The waypoint (fix or navaid) named `id` nearest (ref_lat, ref_lon) [deg].
  const NavPoint* waypoint(std::string_view id, double ref_lat, double ref_lon) const;

  // The threshold of `runway` ("18L", "Y06") at `airport`. A database from
  // load() reads its folder's runway file on the first call (thread-safe);
  // errors name the missing file, airport or runway.
  Result<Threshold> runway(std::string_view airport, std::string_view runway) const;

  size_t airport_count() const { return airports_.size(); }
  const std::vector<NavPoint>& airports() const { return airports_; }
  const std::vector<NavPoint>& waypoints() const { return waypoints_; }
  size_t waypoint_count() const { return waypoints_.size(); }

 private:
  static Result<std::shared_ptr<NavDb>> build(std::string_view airports_dat, std::string_view nav_dat,
                                              std::string_view fix_dat, const std::string& where);

  std::vector<NavPoint> airports_;
  std::vector<std::string>
      airport_names_;  // airports.dat names as name keys (upper-case words joined by
                       // single spaces), by airports_ index (may be empty)
  std::vector<std::string>
      airport_squeezed_;  // airport_names_ without their spaces, by airports_ index
  std::vector<std::string>
      airport_classes_;  // airports.dat classes, upper case, by airports_ index
  std::vector<NavPoint> waypoints_;
  std::vector<std::string> navaid_names_;  // nav.dat names less their kind, as name keys, by
                                           // waypoints_ index (navaids first)
  std::unordered_map<std::string, size_t> airport_index_;
  std::unordered_multimap<std::string, size_t> waypoint_index_;
  std::string dir_;  // load()'s folder: where runway data are read from
  mutable std::once_flag runways_once_;
  mutable std::shared_ptr<const RunwayDb> runways_;
  mutable Status runways_status_;
};

}  // namespace squawk::command
