#include "command/bluesky_only.h"

#include <algorithm>
#include <array>
#include <string>

#include "core/text.h"

namespace squawk::command {

namespace {

// The names squawk lacks that BlueSky's own scenario folder uses (the skipped
// commands of `squawk scn --conformance` over it), sorted for binary search.
constexpr std::array<std::string_view, 86> kNames = {
    "ADDWAYPOINTS", "ADDWPTMODE", "ADSB",      "ASA_ASAS",    "ASA_RESO",    "ASA_ZONEDH",  "ASA_ZONER",
    "BGPASAS",      "CALC",       "CFLLOG",    "COLOR",       "COLOUR",      "CONFLOG",     "CRELOG",
    "CRUISESPD",    "CRZALT",     "CRZSPD",    "DATALOG",     "DATE",        "DEBUG",       "DELALT",
    "DTCPAMBR",     "DTCPCYAN",   "DTCPRED",   "DTLOOKINT",   "DTREACT",     "DTREACTNO",   "DZONEDH",
    "DZONER",       "EVTLOG",     "EXIT",      "FF_ISOALT",   "FF_SNAP",     "FILTAMB",     "FILTRED",
    "FIXDT",        "FR",         "GEOVECTOR", "IMPL",        "INTRLOG",     "LABEL",       "LIMPERF",
    "METRICS",      "NAVDB",      "NAVDT",     "NAVTYPE",     "PAN",         "PLOT",        "PLUGIN",
    "PLUGINS",      "PREDASAS",   "PRIORULES", "PZ",          "QUIT",        "RADARDT",     "RECONACTRTE",
    "RESONR",       "RMETHH",     "ROUTE",     "RRING",       "RSZONEDH",    "RSZONER",     "RTA",
    "SAVEIC",       "SCEN",       "SETMASS",   "SKYLOG",      "SNAPLOG",     "SNAV",        "SSD",
    "STOP",         "SWNLRPASAS", "SWRAD",     "SWSTOPRESO",  "SWTAXI",      "SWTOC",       "SWTOD",
    "SYMBOL",       "SYN",        "TAXI",      "TRAFGEN",     "TRAFLOG",     "TREACT",      "TREACTNO",
    "WINDGFS",      "ZOOM"};

}  // namespace

bool bluesky_only(std::string_view name) {
  if (!name.empty() && (name.find_first_not_of('+') == std::string_view::npos ||
                        name.find_first_not_of('-') == std::string_view::npos))
    return true;
  const std::string up = text::upper(name);
  return std::binary_search(kNames.begin(), kNames.end(), std::string_view(up));
}

}  // namespace squawk::command
