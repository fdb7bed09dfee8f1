// libFuzzer target: the offline translator and the scorer on arbitrary bytes.
// Invariants: no crash, no sanitizer report, and every answer is either a
// question or a non-empty list of non-empty commands.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string>

#include "core/units.h"
#include "translate/offline_translator.h"
#include "translate/scorer.h"

using namespace squawk;
using namespace squawk::translate;

namespace {

const StaticWorld& world() {
  static const StaticWorld w = [] {
    StaticWorld s;
    for (const char* id : {"KLM123", "DAL1153", "AC01"}) {
      AircraftView a;
      a.id = id;
      a.type = "B738";
      a.lat_deg = 52.0;
      a.lon_deg = 4.0;
      a.hdg_deg = 90.0;
      a.alt_m = units::ft_to_m(25000.0);
      a.cas_ms = units::kt_to_ms(280.0);
      a.route = {"ALPHA", "GAYEL"};
      s.add_aircraft(a);
    }
    s.add_waypoint("ALPHA");
    s.add_waypoint("GAYEL");
    return s;
  }();
  return w;
}

void check(const Translation& t) {
  if (t.asked() == !t.commands.empty()) std::abort();
  for (const auto& c : t.commands)
    if (c.empty()) std::abort();
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  Translation bare = translate_offline(text, nullptr);
  check(bare);
  Translation seen = translate_offline(text, &world());
  check(seen);
  (void)score_case(seen.text(), seen.asked(), text);
  (void)score_case(text, false, bare.text());
  return 0;
}
