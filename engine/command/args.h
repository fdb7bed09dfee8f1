// Typed TrafScript arguments: BlueSky's type-list notation and the parser that
// turns a command's argument text into typed values.
//
// Type list (as in BlueSky's command declarations): comma-separated types;
// `[type]` marks an optional argument (everything after the first optional one
// is optional); `a/b` tries the alternatives in order; a trailing `...` repeats
// the last type while text is left. Types:
//   acid       callsign of an existing aircraft, or `*` for all aircraft
//   txt        one token, upper-cased          word    one token, as typed
//   string     the whole rest of the line      float   real   int   integer
//   onoff      on/off switch (formats.h)       alt     altitude [m]
//   spd        CAS [m/s] or Mach (formats.h)   vspd    vertical speed [m/s]
//   hdg        heading [deg]; a name (airport, waypoint, aircraft) gives the
//              bearing to it from the last aircraft parsed on the line. An
//              optional heading may be `*`: omitted (CRE then takes a runway's
//              heading; BlueSky itself refuses `*` there)
//   time       [s]
//   latlon     a position: lat lon (two tokens), an aircraft, an airport,
//              a runway threshold (APT/RW18L, APT/RWY18L or APT RW18L; its
//              bearing becomes the value's ref_hdg, as BlueSky's ref.hdg), a user
//              waypoint (DEFWPT), a fix or navaid (nearest the reference)
//   wpt        like latlon, and keeps the name (empty for lat/lon pairs)
//   wpinroute  a waypoint name in the route of the last acid parsed, or `*`
//
// The reference position (BlueSky's bs.ref, bluesky/refdata.py): a parse
// starts from ParseContext::ref; an acid parsed moves it to that aircraft, a
// latlon parsed moves it to the position (not when the position is an
// aircraft: BlueSky's PosArg returns an aircraft's position without moving
// it); wpt and hdg do not move it (BlueSky's WptArg and txt2hdg read it only).
// ParsedArgs::ref is where it ends; the stack keeps it between commands.
// Parsing only reads the context; it never changes the simulation.
#pragma once

#include <limits>
#include <map>
#include <string>
#include <string_view>
#include <vector>

#include "command/formats.h"
#include "command/navdb.h"
#include "core/status.h"
#include "sim/traffic.h"

namespace squawk::command {

enum class ArgType {
  kAcid, kTxt, kWord, kString, kFloat, kInt, kOnOff, kAlt, kSpd, kVspd, kHdg, kTime,
  kLatLon, kWpt, kWpInRoute,
};

const char* arg_type_name(ArgType t);
// A noun for messages ("altitude", "aircraft id", ...).
const char* arg_type_noun(ArgType t);

struct ParamSpec {
  std::vector<ArgType> alternatives;  // tried in order
  bool optional = false;
};

struct Signature {
  std::vector<ParamSpec> params;
  bool repeat_last = false;  // "..." after the last type
};

// Parses a type list such as "acid,alt,[vspd]". Error names the bad type.
Result<Signature> parse_signature(std::string_view types);

struct GeoPoint {
  double lat = 0.0;  // [deg]
  double lon = 0.0;  // [deg]
};

struct ArgValue {
  bool present = false;      // false: omitted (the handler applies its default)
  ArgType type = ArgType::kWord;  // the alternative that matched
  std::string text;          // the token (upper-cased for all but word/string)
  double num = 0.0;          // alt [m], vspd [m/s], hdg [deg], time [s], float, int
  Speed spd;                 // spd
  bool on = false;           // onoff
  GeoPoint pos;              // latlon, wpt
  double ref_hdg = std::numeric_limits<double>::quiet_NaN();  // latlon of a runway: its bearing [deg]
  std::vector<int> acids;    // acid: traffic indices (one, or all for `*`)
};

// What the parser may read: traffic, navigation data and user waypoints.
struct ParseContext {
  const sim::Traffic* traffic = nullptr;
  const NavDb* navdb = nullptr;                          // null: no navdata loaded
  const std::map<std::string, GeoPoint>* user_wpts = nullptr;  // DEFWPT, upper-case names
  GeoPoint ref;  // the reference position the parse starts from (see above)
};

// The values of a parse and the reference position after it.
struct ParsedArgs {
  std::vector<ArgValue> values;
  GeoPoint ref;
};

// Resolves one position token (and possibly the next token, for lat lon and
// "APT RWxx") read from `reader` text. `ref` is the reference position for
// nearest-navaid lookup. Error names the token and what it could have been.
class ArgReader;
Result<ArgValue> parse_position(ArgReader& reader, const ParseContext& ctx, GeoPoint ref);

// Parses `argtext` against `sig`, starting from the reference ctx.ref. Errors
// name the argument position, its type and the token, and are prefixed by
// nothing (the caller adds the command).
Result<ParsedArgs> parse_args(const Signature& sig, std::string_view argtext,
                              const ParseContext& ctx);

}  // namespace squawk::command
