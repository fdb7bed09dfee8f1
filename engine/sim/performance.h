// Simple aircraft performance limits by type class.
//
// squawk does not embed OpenAP or BADA tables. An ICAO type designator maps to
// one of four classes, each with fixed envelope limits (values below, chosen
// from typical published envelopes of the class; not from any table):
//
//   class       vmin   vmax   (CAS, m/s)  vsmax  (m/s)  hmax (m)  axmax (m/s^2)
//   jet          50     180                 25          12500      0.5
//   turboprop    40     130                 12.5         7600      0.5
//   piston       25      90                  5           4500      0.5
//   helicopter    0      80                 10           3000      0.5
//
// vsmin = -vsmax. axmax 0.5 m/s^2 airborne is BlueSky's OpenAP airborne value.
//
// Ground-phase cap (option, off by default): BlueSky's default OpenAP model
// puts an aircraft at or below 75 ft in phase GD, where vmax becomes the type's
// initial-climb speed (89 m/s for the A320) and axmax 2 m/s^2. BlueSky-Gym
// creates its aircraft at altitude 0, so they slow from 150 to 89 m/s
// (docs/bluesky_facts.md §6). With `ground_cap` on, the same rule applies
// here to every class: alt <= ground_alt -> vmax = ground_vmax, axmax =
// ground_axmax.
#pragma once

#include <string_view>
#include <utility>
#include <vector>

namespace squawk::sim {

enum class PerfClass { kJet = 0, kTurboprop = 1, kPiston = 2, kHelicopter = 3 };

struct PerfLimits {
  double vmin;   // [m/s] CAS
  double vmax;   // [m/s] CAS
  double vsmin;  // [m/s] (negative: the steepest descent)
  double vsmax;  // [m/s]
  double hmax;   // [m] ceiling
  double axmax;  // [m/s^2] airborne longitudinal acceleration limit
  double mmo = 1e9;  // [-] maximum Mach (OpenAP; none in the class table)
};

struct PerformanceOptions {
  bool ground_cap = false;        // emulate OpenAP's ground phase (see above)
  double ground_alt = 75 * 0.3048;  // [m] at or below this, the ground cap applies
  double ground_vmax = 89.0;      // [m/s] CAS limit in the ground phase
  double ground_axmax = 2.0;      // [m/s^2] acceleration limit in the ground phase
};

// Class of an ICAO type designator (case-insensitive); unknown types are jets.
PerfClass perf_class_of(std::string_view actype);
// The designators the class model lists by name (turboprops, pistons,
// helicopters; any other type is a jet), with their class.
std::vector<std::pair<std::string_view, PerfClass>> class_model_types();
const char* perf_class_name(PerfClass c);
// The fixed limits of a class (table above).
const PerfLimits& perf_limits(PerfClass c);

}  // namespace squawk::sim
