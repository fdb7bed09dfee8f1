#include "command/runways.h"

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <fstream>
#include <vector>

#include "core/files.h"
#include "core/geo.h"
#include "core/text.h"
#include "core/zip.h"

namespace squawk::command {

// Line-by-line apt.dat reader fed in chunks (a world apt.dat is hundreds of MB).
class RunwayDb::Reader {
 public:
  Reader(RunwayDb& db, const std::string& where) : db_(db), where_(where) {}

  Status feed(std::string_view chunk) {
    size_t at = 0;
    for (size_t nl; (nl = chunk.find('\n', at)) != std::string_view::npos; at = nl + 1) {
      if (partial_.empty()) {
        SQUAWK_RETURN_IF_ERROR(line(chunk.substr(at, nl - at)));
      } else {
        partial_.append(chunk.substr(at, nl - at));
        SQUAWK_RETURN_IF_ERROR(line(partial_));
        partial_.clear();
      }
    }
    partial_.append(chunk.substr(at));
    if (partial_.size() > kMaxLine) return error("line longer than " + std::to_string(kMaxLine) + " bytes");
    return Status::ok();
  }
  Status finish() {
    if (!partial_.empty()) SQUAWK_RETURN_IF_ERROR(line(partial_));
    return Status::ok();
  }

 private:
  static constexpr size_t kMaxLine = 64 * 1024;

  Status error(const std::string& what) const {
    return Status::corruption(where_ + ":" + std::to_string(lineno_) + ": " + what);
  }

  // The row code: the first field (a world apt.dat has millions of rows; only
  // four codes are split into fields).
  static std::string_view row_code(std::string_view raw) {
    size_t i = 0;
    while (i < raw.size() && std::isspace(static_cast<unsigned char>(raw[i]))) ++i;
    size_t j = i;
    while (j < raw.size() && !std::isspace(static_cast<unsigned char>(raw[j]))) ++j;
    return raw.substr(i, j - i);
  }

  Status line(std::string_view raw) {
    ++lineno_;
    const std::string_view code = row_code(raw);
    if (code != "1" && code != "16" && code != "17" && code != "100") return Status::ok();
    const auto f = text::split_ws(raw);
    if (f[0] == "1" || f[0] == "16" || f[0] == "17") {
      if (f.size() < 5) return error("airport header needs an ICAO code in field 5");
      current_ = &db_.airports_[text::upper(f[4])];
      return Status::ok();
    }
    if (f.size() < 21) return error("runway row has " + std::to_string(f.size()) + " fields, expected at least 21");
    if (!current_) return error("runway row before any airport header");
    const auto surface = text::to_int(f[2]);
    if (!surface) return error("runway surface " + text::quoted(f[2]) + " is not an integer");
    if (*surface > 2) return Status::ok();  // only asphalt and concrete, as BlueSky
    double v[6];
    const size_t idx[6] = {9, 10, 11, 18, 19, 20};
    for (int k = 0; k < 6; ++k) {
      const auto d = text::to_double(f[idx[k]]);
      if (!d) return error("runway field " + std::to_string(idx[k] + 1) + " " + text::quoted(f[idx[k]]) + " is not a number");
      v[k] = *d;
    }
    for (int k : {0, 3})
      if (std::abs(v[k]) > 90.0 || std::abs(v[k + 1]) > 180.0 || v[k + 2] < 0.0)
        return error("runway end " + text::quoted(f[k == 0 ? 8 : 17]) + ": lat/lon out of range or negative displacement");
    (*current_)[text::upper(f[8])] = threshold(v[0], v[1], v[3], v[4], v[2]);
    (*current_)[text::upper(f[17])] = threshold(v[3], v[4], v[0], v[1], v[5]);
    return Status::ok();
  }

  // The end (lat, lon) moved `offset` [m] toward the other end (olat, olon).
  static Threshold threshold(double lat, double lon, double olat, double olon, double offset) {
    const double brg = geo::gc_bearing_deg(lat, lon, olat, olon);
    const auto p = geo::gc_destination(lat, lon, brg, offset);
    return {p.lat_deg, p.lon_deg, brg};
  }

  RunwayDb& db_;
  std::string where_;
  std::string partial_;
  size_t lineno_ = 0;
  std::unordered_map<std::string, Threshold>* current_ = nullptr;
};

Result<std::shared_ptr<const RunwayDb>> RunwayDb::read(const std::string& where,
                                                       const std::function<Status(const Sink&)>& source) {
  auto db = std::make_shared<RunwayDb>();
  db->where_ = where;
  Reader r(*db, where);
  SQUAWK_RETURN_IF_ERROR(source([&](std::string_view chunk) { return r.feed(chunk); }));
  SQUAWK_RETURN_IF_ERROR(r.finish());
  return std::shared_ptr<const RunwayDb>(std::move(db));
}

Result<std::shared_ptr<const RunwayDb>> RunwayDb::parse(std::string_view apt_dat, const std::string& where) {
  return read(where, [&](const Sink& sink) { return sink(apt_dat); });
}

Result<std::shared_ptr<const RunwayDb>> RunwayDb::load(const std::string& dir) {
  if (const std::string path = dir + "/apt.dat"; files::exists(path)) {
    std::error_code ec;
    if (!std::filesystem::is_regular_file(path, ec)) return Status::io_error(path + ": not a regular file");
    std::ifstream in(path, std::ios::binary);
    if (!in) return Status::io_error(path + ": cannot open");
    // Streamed: X-Plane's world file is hundreds of MB.
    return read(path, [&](const Sink& sink) {
      std::vector<char> buf(1 << 20);
      while (in) {
        in.read(buf.data(), static_cast<std::streamsize>(buf.size()));
        if (in.gcount() > 0) SQUAWK_RETURN_IF_ERROR(sink(std::string_view(buf.data(), static_cast<size_t>(in.gcount()))));
      }
      return in.bad() ? Status::io_error(path + ": read error") : Status::ok();
    });
  }
  const std::string zip_path = dir + "/apt.zip";
  if (!files::exists(zip_path))
    return Status::not_found("navdata folder '" + dir +
                             "' has no apt.dat or apt.zip (runway thresholds; BlueSky ships them as resources/navdata/apt.zip)");
  SQUAWK_ASSIGN_OR_RETURN(std::string archive, files::read(zip_path));
  return read(zip_path + ":apt.dat", [&](const Sink& sink) { return zip::read_member(archive, "apt.dat", zip_path, sink); });
}

Result<Threshold> RunwayDb::find(std::string_view airport, std::string_view runway) const {
  std::string rwy = text::upper(runway);
  rwy.erase(0, rwy.find_first_not_of('Y'));
  if (!rwy.empty() && std::isdigit(static_cast<unsigned char>(rwy[0])) &&
      (rwy.size() == 1 || !std::isdigit(static_cast<unsigned char>(rwy[1]))))
    rwy.insert(0, "0");
  const std::string apt = text::upper(airport);
  const std::string name = apt + "/RW" + std::string(runway);
  auto a = airports_.find(apt);
  if (a == airports_.end() || a->second.empty())
    return Status::not_found("runway " + text::quoted(name) + ": " + where_ + " lists no asphalt or concrete runways for " + apt);
  if (auto r = a->second.find(rwy); r != a->second.end()) return r->second;
  std::vector<std::string> names;
  for (const auto& [n, _] : a->second) names.push_back(n);
  std::sort(names.begin(), names.end());
  return Status::not_found("runway " + text::quoted(name) + ": " + apt + " has runways " + text::join(names, ", "));
}

}  // namespace squawk::command
