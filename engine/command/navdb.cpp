#include "command/navdb.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <limits>
#include <map>
#include <mutex>
#include <set>

#include "core/files.h"
#include "core/geo.h"
#include "core/text.h"

namespace squawk::command {

namespace {

// Lines of a text file, CR/LF/CRLF tolerant.
std::vector<std::string_view> lines_of(std::string_view data) {
  std::vector<std::string_view> out;
  size_t start = 0;
  for (size_t i = 0; i < data.size(); ++i) {
    if (data[i] == '\n' || data[i] == '\r') {
      out.push_back(data.substr(start, i - start));
      if (data[i] == '\r' && i + 1 < data.size() && data[i + 1] == '\n') ++i;
      start = i + 1;
    }
  }
  if (start < data.size()) out.push_back(data.substr(start));
  return out;
}

// Upper-case words of a name, punctuation dropped, joined by single spaces.
std::string name_key(std::string_view name) {
  std::string out;
  bool gap = false;
  for (char c : name) {
    if (std::isalnum(static_cast<unsigned char>(c))) {
      if (gap && !out.empty()) out.push_back(' ');
      out.push_back(static_cast<char>(std::toupper(static_cast<unsigned char>(c))));
      gap = false;
    } else {
      gap = true;
    }
  }
  return out;
}

// A name key without its spaces ("LA GUARDIA" -> "LAGUARDIA").
std::string squeezed(std::string s) {
  s.erase(std::remove(s.begin(), s.end(), ' '), s.end());
  return s;
}

// True when `run` (words) is a run of whole words of `name` (words joined by single spaces).
bool holds_run(std::string_view name, std::string_view run) {
  for (size_t p = name.find(run); p != std::string_view::npos; p = name.find(run, p + 1))
    if ((p == 0 || name[p - 1] == ' ') &&
        (p + run.size() == name.size() || name[p + run.size()] == ' '))
      return true;
  return false;
}

bool valid_latlon(double lat, double lon) { return std::fabs(lat) <= 90.0 && std::fabs(lon) <= 180.0; }

Status parse_airports(std::string_view data, const std::string& path, std::vector<NavPoint>& out,
                      std::vector<std::string>& names, std::vector<std::string>& classes) {
  size_t lineno = 0;
  for (auto raw : lines_of(data)) {
    ++lineno;
    std::string_view line = text::trim(raw);
    if (line.empty() || line.front() == '#') continue;
    const auto f = text::split(line, ',');
    if (f.size() < 4) continue;
    auto lat = text::to_double(f[2]);
    auto lon = text::to_double(f[3]);
    const std::string id = text::upper(text::trim(f[0]));
    if (!lat || !lon || id.empty() || !valid_latlon(*lat, *lon))
      return Status::corruption(path + ":" + std::to_string(lineno) +
                                ": expected 'code, name, lat, lon, ...' with lat/lon in degrees");
    out.push_back({id, "APT", *lat, *lon});
    names.push_back(text::upper(text::trim(f[1])));
    classes.push_back(f.size() > 4 ? text::upper(text::trim(f[4])) : std::string());
  }
  return Status::ok();
}

// A navaid's name as nav.dat writes it after the ident, less its kind ("SAN FRANCISCO VOR-DME" ->
// "SAN FRANCISCO").
std::string navaid_name(const std::vector<std::string>& f) {
  static const char* kKinds[] = {"VOR",     "VOR-DME", "VORTAC", "NDB",
                                 "NDB-DME", "DME",     "TACAN",  "DME-ILS"};
  size_t end = f.size();
  if (end > 9 && std::any_of(std::begin(kKinds), std::end(kKinds),
                             [&](const char* k) { return text::upper(f[end - 1]) == k; }))
    --end;
  std::string name;
  for (size_t i = 8; i < end; ++i) name += (name.empty() ? "" : " ") + text::upper(f[i]);
  return name;
}

void parse_navaids(std::string_view data, std::vector<NavPoint>& out,
                   std::vector<std::string>& names) {
  for (auto raw : lines_of(data)) {
    const auto f = text::split_ws(raw);
    if (f.size() < 8) continue;
    auto type = text::to_int(f[0]);
    if (!type) continue;
    const char* name = *type == 2 ? "NDB" : *type == 3 ? "VOR" : *type == 12 ? "DME" : *type == 13 ? "TACAN" : nullptr;
    if (!name) continue;
    auto lat = text::to_double(f[1]);
    auto lon = text::to_double(f[2]);
    if (!lat || !lon || !valid_latlon(*lat, *lon)) continue;
    out.push_back({text::upper(f[7]), name, *lat, *lon});
    names.push_back(name_key(navaid_name(f)));
  }
}

void parse_fixes(std::string_view data, std::vector<NavPoint>& out) {
  for (auto raw : lines_of(data)) {
    const auto f = text::split_ws(raw);
    if (f.size() < 3) continue;
    auto lat = text::to_double(f[0]);
    auto lon = text::to_double(f[1]);
    if (!lat || !lon || !valid_latlon(*lat, *lon)) continue;
    out.push_back({text::upper(f[2]), "FIX", *lat, *lon});
  }
}

}  // namespace

NavDb::NavDb(std::vector<NavPoint> airports, std::vector<NavPoint> waypoints,
             std::shared_ptr<const RunwayDb> runways)
    : airports_(std::move(airports)), waypoints_(std::move(waypoints)), runways_(std::move(runways)) {
  for (size_t i = 0; i < airports_.size(); ++i) airport_index_.emplace(airports_[i].id, i);
  for (size_t i = 0; i < waypoints_.size(); ++i) waypoint_index_.emplace(waypoints_[i].id, i);
}

Result<std::shared_ptr<const NavDb>> NavDb::load(const std::string& dir) {
  SQUAWK_ASSIGN_OR_RETURN(std::string apt, files::read(dir + "/airports.dat"));
  SQUAWK_ASSIGN_OR_RETURN(std::string nav, files::read(dir + "/nav.dat"));
  SQUAWK_ASSIGN_OR_RETURN(std::string fix, files::read(dir + "/fix.dat"));
  SQUAWK_ASSIGN_OR_RETURN(std::shared_ptr<NavDb> db, build(apt, nav, fix, dir));
  db->dir_ = dir;
  return std::shared_ptr<const NavDb>(std::move(db));
}

Result<Threshold> NavDb::runway(std::string_view airport, std::string_view runway) const {
  std::call_once(runways_once_, [this] {
    if (runways_) return;
    if (dir_.empty()) {
      runways_status_ = Status::not_found("no runway data: this navigation database was not read from a folder");
      return;
    }
    auto db = RunwayDb::load(dir_);
    if (db) runways_ = *db;
    else runways_status_ = db.status();
  });
  if (!runways_)
    return runways_status_.with_context("runway " + text::quoted(std::string(airport) + "/RW" + std::string(runway)));
  return runways_->find(airport, runway);
}

Result<std::shared_ptr<const NavDb>> NavDb::parse(std::string_view airports_dat, std::string_view nav_dat,
                                                  std::string_view fix_dat, const std::string& where) {
  SQUAWK_ASSIGN_OR_RETURN(std::shared_ptr<NavDb> db, build(airports_dat, nav_dat, fix_dat, where));
  return std::shared_ptr<const NavDb>(std::move(db));
}

Result<std::shared_ptr<NavDb>> NavDb::build(std::string_view airports_dat, std::string_view nav_dat,
                                            std::string_view fix_dat, const std::string& where) {
  std::vector<NavPoint> airports, waypoints;
  std::vector<std::string> names, classes, navaid_names;
  SQUAWK_RETURN_IF_ERROR(
      parse_airports(airports_dat, where + "/airports.dat", airports, names, classes));
  parse_navaids(nav_dat, waypoints, navaid_names);
  parse_fixes(fix_dat, waypoints);
  if (airports.empty() && waypoints.empty())
    return Status::corruption("navdata folder '" + where + "' holds no airports, navaids or fixes");
  auto db = std::make_shared<NavDb>(std::move(airports), std::move(waypoints));
  for (std::string& n : names) {
    n = name_key(n);
    db->airport_squeezed_.push_back(squeezed(n));
  }
  db->airport_names_ = std::move(names);
  db->airport_classes_ = std::move(classes);
  db->navaid_names_ = std::move(navaid_names);
  return db;
}

Result<std::shared_ptr<const NavDb>> NavDb::load_cached(const std::string& dir) {
  static std::mutex mu;
  static std::map<std::string, std::shared_ptr<const NavDb>> cache;
  std::lock_guard<std::mutex> lock(mu);
  if (auto it = cache.find(dir); it != cache.end()) return it->second;
  SQUAWK_ASSIGN_OR_RETURN(auto db, load(dir));
  cache.emplace(dir, db);
  return db;
}

std::vector<const NavPoint*> NavDb::airports_named(std::string_view name) const {
  std::vector<const NavPoint*> out;
  std::string key = name_key(name);
  if (key.empty()) return out;
  // "Denver International": the navdata writes the word INTL ("DENVER INTL")
  static const std::string kSaid = " INTERNATIONAL";
  if (key.size() > kSaid.size() && key.compare(key.size() - kSaid.size(), kSaid.size(), kSaid) == 0)
    key = key.substr(0, key.size() - kSaid.size()) + " INTL";
  // words a name may carry after the part people say ("Schiphol Airport")
  static const char* kGeneric[] = {"AIRPORT", "INTERNATIONAL", "INTL", "AIRFIELD", "AERODROME", "AIRBASE", "AIR BASE"};
  // a name said as one word that the navdata writes as two ("LaGuardia": LA GUARDIA), or the other
  // way
  const std::string key_squeezed = squeezed(key);
  for (size_t i = 0;
       i < airport_names_.size() && i < airport_squeezed_.size() && i < airports_.size(); ++i) {
    const std::string& n = airport_names_[i];
    bool fits = n == key || airport_squeezed_[i] == key_squeezed;
    if (!fits && n.size() > key.size() + 1 && n.compare(0, key.size(), key) == 0 && n[key.size()] == ' ') {
      const std::string rest = n.substr(key.size() + 1);
      fits = std::any_of(std::begin(kGeneric), std::end(kGeneric), [&](const char* g) { return rest == g; });
    }
    if (fits) out.push_back(&airports_[i]);
  }
  return out;
}

std::vector<const NavPoint*> NavDb::airports_of_city(std::string_view city) const {
  std::vector<const NavPoint*> out;
  const std::string key = name_key(city);
  if (key.empty()) return out;
  for (size_t i = 0;
       i < airport_names_.size() && i < airport_classes_.size() && i < airports_.size(); ++i) {
    const std::string& n = airport_names_[i];
    // ("Panama" is no city of "PANAMA CITY BAY CO INTL": a name followed by CITY is a country's or
    // a state's, the city another)
    if (airport_classes_[i] == "LARGE" && n.size() > key.size() + 1 &&
        n.compare(0, key.size(), key) == 0 && n[key.size()] == ' ' &&
        n.compare(key.size() + 1, 4, "CITY") != 0)
      out.push_back(&airports_[i]);
  }
  return out;
}

std::vector<const NavPoint*> NavDb::airports_with_words(std::string_view words) const {
  std::vector<const NavPoint*> out;
  // words of many airports' names that tell what kind of field it is, not which
  static const std::set<std::string> kKind = {
      "AIRPORT", "INTL",  "AIRFIELD",     "AERODROME", "AIRBASE",  "AIR",      "BASE", "AFB",
      "FLD",     "MUNI",  "RGNL",         "CO",        "COUNTY",   "CITY",     "MEML", "EXEC",
      "NATL",    "METRO", "METROPOLITAN", "STRIP",     "HELIPORT", "SEAPLANE", "PORT", "ARPT"};
  // such words as said, and as the navdata writes them ("Dallas Love Field": DALLAS LOVE FLD)
  static const std::map<std::string, std::string> kWritten = {
      {"INTERNATIONAL", "INTL"}, {"FIELD", "FLD"},      {"MUNICIPAL", "MUNI"}, {"REGIONAL", "RGNL"},
      {"MEMORIAL", "MEML"},      {"EXECUTIVE", "EXEC"}, {"NATIONAL", "NATL"}};
  const std::string said = name_key(words);
  std::string key;
  bool kind_only = true;
  for (size_t b = 0; b < said.size();) {
    const size_t e = std::min(said.find(' ', b), said.size());
    std::string w = said.substr(b, e - b);
    if (auto it = kWritten.find(w); it != kWritten.end()) w = it->second;
    kind_only = kind_only && kKind.count(w) > 0;
    key += (key.empty() ? "" : " ") + w;
    b = e + 1;
  }
  if (key.empty() || kind_only) return out;
  for (size_t i = 0; i < airport_names_.size() && i < airports_.size(); ++i) {
    if (holds_run(airport_names_[i], key)) out.push_back(&airports_[i]);
  }
  return out;
}

std::vector<const NavPoint*> NavDb::airports_beside_navaids(std::string_view name) const {
  std::vector<const NavPoint*> out;
  const std::string key = name_key(name);
  if (key.empty()) return out;
  // airports of class `cls` within `nm` of a navaid called `name`, each once
  auto within = [&](const char* cls, double nm) {
    std::vector<const NavPoint*> found;
    for (size_t w = 0; w < navaid_names_.size() && w < waypoints_.size(); ++w) {
      if (navaid_names_[w] != key) continue;
      for (size_t i = 0; i < airports_.size() && i < airport_classes_.size(); ++i) {
        const NavPoint& a = airports_[i];
        if (airport_classes_[i] == cls &&
            geo::kwikdist_nm(a.lat, a.lon, waypoints_[w].lat, waypoints_[w].lon) <= nm &&
            std::find(found.begin(), found.end(), &a) == found.end())
          found.push_back(&a);
      }
    }
    return found;
  };
  out = within("LARGE", kBesideNavaidNm);
  if (!out.empty()) {
    for (const NavPoint* a : within("LARGE", kCityNm))
      if (std::find(out.begin(), out.end(), a) == out.end()) out.push_back(a);
    return out;
  }
  return within("MEDIUM", kBesideNavaidNm);
}

std::string NavDb::airport_class(std::string_view id) const {
  for (size_t i = 0; i < airports_.size() && i < airport_classes_.size(); ++i)
    if (airports_[i].id == id) return airport_classes_[i];
  return std::string();
}

std::vector<const NavPoint*> NavDb::navaids_named(std::string_view name, double ref_lat,
                                                  double ref_lon, double within_nm,
                                                  std::string_view types, bool run) const {
  std::vector<std::pair<double, size_t>> found;
  const std::string key = name_key(name);
  if (key.empty()) return {};
  const std::string kinds = " " + text::upper(types) + " ";
  for (size_t i = 0; i < navaid_names_.size() && i < waypoints_.size(); ++i) {
    if (run ? !holds_run(navaid_names_[i], key) : navaid_names_[i] != key) continue;
    const NavPoint& p = waypoints_[i];
    if (!types.empty() && kinds.find(" " + p.type + " ") == std::string::npos) continue;
    const double d = geo::kwikdist_nm(ref_lat, ref_lon, p.lat, p.lon);
    if (d <= within_nm) found.emplace_back(d, i);
  }
  std::sort(found.begin(), found.end());
  std::vector<const NavPoint*> out;
  for (const auto& f : found) {
    const NavPoint* p = &waypoints_[f.second];
    if (std::none_of(out.begin(), out.end(), [&](const NavPoint* q) { return q->id == p->id; }))
      out.push_back(p);
  }
  return out;
}

const NavPoint* NavDb::airport(std::string_view id) const {
  auto it = airport_index_.find(text::upper(id));
  return it == airport_index_.end() ? nullptr : &airports_[it->second];
}

const NavPoint* NavDb::waypoint(std::string_view id, double ref_lat, double ref_lon) const {
  auto [lo, hi] = waypoint_index_.equal_range(text::upper(id));
  const NavPoint* best = nullptr;
  double best_d = std::numeric_limits<double>::infinity();
  for (auto it = lo; it != hi; ++it) {
    const NavPoint& p = waypoints_[it->second];
    const double d = geo::kwikdist_nm(ref_lat, ref_lon, p.lat, p.lon);
    if (d < best_d || (d == best_d && best && it->second < static_cast<size_t>(best - waypoints_.data()))) {
      best_d = d;
      best = &p;
    }
  }
  return best;
}

}  // namespace squawk::command
