// Text formats of TrafScript argument values, converted to SI at this edge.
//
// Each parser takes one token and returns the value or an error whose message
// quotes the token and names the expected form. Accepted forms follow
// BlueSky's bluesky/tools/misc.py and tools/position.py (docs/bluesky_facts.md §2.2):
//   altitude   FL300 / fl300 (FL + integer, at least 4 characters) or feet  -> [m]
//   speed      knots CAS (250) or Mach: M.78, M0.78, M78, .78, 0.78          -> Speed
//   vspeed     feet per minute                                             -> [m/s]
//   heading    090, 236.9T, M270, -10 (T/M prefix or suffix, not wrapped)  -> [deg]
//   time       SS.hh, MM:SS.hh, HH:MM:SS.hh                                -> [s]
//   latitude   52.3, -52.3, N52.3, S12'30'00", N52'18'00.5                  -> [deg]
//   longitude  4.5, -4.5, 4e0, E004'23'10", W002', W65 (also the ° sign)    -> [deg]
//   on/off     true yes y 1 on / false no n 0 off (any case)
// Magnetic headings (M) are read as true: squawk has no declination model.
#pragma once

#include <string_view>

#include "core/status.h"

namespace squawk::command {

// A speed as typed: knots CAS (stored as m/s) or a Mach number in (0.1, 2).
// `value` follows the simulator's casmach convention (sim/atmosphere.h
// is_mach): a value in (0.1, 2) is Mach, anything else CAS [m/s]. Knots
// below 3.9 are thus read as Mach, as in BlueSky.
struct Speed {
  bool is_mach = false;
  double value = 0.0;  // [m/s] CAS when !is_mach, else [-] Mach number
};

Result<double> parse_alt(std::string_view token);    // [m]
Result<Speed> parse_spd(std::string_view token);
Result<double> parse_vspd(std::string_view token);   // [m/s]
Result<double> parse_hdg(std::string_view token);    // [deg], as typed (not wrapped)
Result<double> parse_time(std::string_view token);   // [s]
Result<double> parse_lat(std::string_view token);    // [deg], in [-90, 90]
Result<double> parse_lon(std::string_view token);    // [deg], wrapped into [-180, 180)
Result<bool> parse_onoff(std::string_view token);
Result<double> parse_float(std::string_view token);  // finite real
Result<long long> parse_int(std::string_view token);

// True when `token` looks like a latitude (BlueSky's islat): after a sign,
// quotes, dots and one N/S are dropped, a number remains (exponents allowed,
// as in -5.5e-17). Decides whether a position is a lat/lon pair or a name.
bool is_lat(std::string_view token);

// True when `token` is a heading number (parse_hdg accepts it without a lookup).
bool is_hdg_number(std::string_view token);

}  // namespace squawk::command
