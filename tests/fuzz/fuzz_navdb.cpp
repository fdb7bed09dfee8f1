// libFuzzer target: the navdata readers on arbitrary bytes. The input is split
// at its first three NUL bytes into airports.dat, nav.dat, fix.dat and the
// runway file (the rest, NULs included): apt.dat text, or apt.zip when it
// starts with "PK". A database that loads must answer lookups of its own names.
#include <cstdint>
#include <string>
#include <string_view>

#include "command/navdb.h"
#include "command/runways.h"
#include "core/zip.h"

using namespace squawk;

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  std::string_view in(reinterpret_cast<const char*>(data), size);
  std::string_view part[4];
  for (int k = 0; k < 3; ++k) {
    const size_t nul = in.find('\0');
    part[k] = in.substr(0, nul);
    in = nul == std::string_view::npos ? std::string_view() : in.substr(nul + 1);
  }
  part[3] = in;
  auto db = command::NavDb::parse(part[0], part[1], part[2], "fuzz");
  if (db) {
    for (const auto& a : (*db)->airports())
      if ((*db)->airport(a.id) == nullptr) __builtin_trap();
    for (const auto& w : (*db)->waypoints())
      if ((*db)->waypoint(w.id, w.lat, w.lon) == nullptr) __builtin_trap();
  }
  std::string apt(part[3]);
  if (apt.rfind("PK", 0) == 0) {
    std::string out;
    const Status st = zip::read_member(part[3], "apt.dat", "fuzz.zip", [&](std::string_view c) {
      out.append(c);
      return Status::ok();
    });
    if (!st.is_ok()) return 0;
    apt = std::move(out);
  }
  auto rwy = command::RunwayDb::parse(apt, "fuzz/apt.dat");
  if (rwy) (void)(*rwy)->find("EHAM", "18L");
  return 0;
}
