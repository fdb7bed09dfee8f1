// libFuzzer target: the navdata reader (airports.dat, nav.dat, fix.dat) on
// arbitrary bytes, split into the three files at the first two NUL bytes;
// a database that loads must answer lookups of its own names.
#include <cstdint>
#include <string_view>

#include "command/navdb.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  std::string_view in(reinterpret_cast<const char*>(data), size);
  std::string_view part[3];
  for (int k = 0; k < 2; ++k) {
    const size_t nul = in.find('\0');
    part[k] = in.substr(0, nul);
    in = nul == std::string_view::npos ? std::string_view() : in.substr(nul + 1);
  }
  part[2] = in;
  auto db = squawk::command::NavDb::parse(part[0], part[1], part[2], "fuzz");
  if (!db) return 0;
  for (const auto& a : (*db)->airports())
    if ((*db)->airport(a.id) == nullptr) __builtin_trap();
  for (const auto& w : (*db)->waypoints())
    if ((*db)->waypoint(w.id, w.lat, w.lon) == nullptr) __builtin_trap();
  return 0;
}
