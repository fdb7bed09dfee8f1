// OpenAP aircraft performance data, read from a folder squawk is given.
//
// OpenAP (github.com/junzis/openap, LGPL-3.0) is not part of squawk: its
// `data` folder (the one `pip install openap` installs) is read at run time
// from a path named by SQUAWK_OPENAP, `--openap DIR` or `PERF OPENAP DIR`.
// Nothing here is compiled from OpenAP; the file layout and the way BlueSky's
// OpenAP performance model condenses the files into per-type limits are facts
// (BlueSky traffic/performance/openap/coeff.py at 22fdf9e):
//
//   aircraft/<type>.yml   mtow, oew, wing.area, wing.span, engine.number,
//                         engine.default, engine.mount
//   engine/engines.csv    first row whose name starts with engine.default:
//                         max_thrust [N], bpr
//   dragpolar/<type>.yml  clean.cd0, clean.k, gears, flaps.lambda_f,
//                         flaps.cf/c, flaps.Sf/S
//   wrap/<type>.txt       WRAP kinematic variables: opt, min, max columns
//   */_synonym.csv        orig,new: a type without its own file uses `new`
//
// Limits per type (all SI): vminto = to_v_lof.min; vminic/vmaxic =
// ic_va_avg.min/max; vminer/vmaxer = min/max over ic_va_avg, cl_v_cas_const,
// cr_v_cas_mean, de_v_cas_const, fa_va_avg; vminap/vmaxap = fa_va_avg;
// mmo = cr_v_mach_max.opt; hmax = 1000 cr_h_max.opt; axmax0 =
// to_acc_tof.max; vsmax = max over ic_vs_avg, cl_vs_avg_pre_cas,
// cl_vs_avg_cas_const, cl_vs_avg_mach_const (.max); mass = (oew + mtow)/2.
// Drag: cd0_to = cd0 + lambda_f (cf/c)^1.38 (Sf/S) sin^2(15 deg), cd0_ld the
// same at 40 deg; k_to = 1/(1/k + pi AR de), de = 0.0046 (rear-mounted
// engines) or 0.0026 per flap degree (15 / 40 deg), AR = span^2/area.
//
// Types are the aircraft files plus the aircraft synonyms; a type whose WRAP
// or drag polar cannot be found is left out. find() maps an unknown type to
// B744, as BlueSky does (rotorcraft included: BlueSky's rotor table is not
// part of OpenAP's data).
#pragma once

#include <map>
#include <memory>
#include <string>
#include <utility>
#include <vector>
#include <string_view>

#include "core/status.h"

namespace squawk::sim {

struct OpenapType {
  std::string name;  // upper-case type the data came from (after synonyms)
  std::string title; // the aircraft as the data names it ("Boeing 777-300ER"); empty for a synonym
  // Speed envelope, CAS [m/s]
  double vminto = 0, vminic = 0, vmaxic = 0, vminer = 0, vmaxer = 0, vminap = 0, vmaxap = 0;
  double mmo = 0;      // [-]
  double hmax = 0;     // [m] ceiling
  double vsmax = 0;    // [m/s] climb-rate limit
  double vsmin = 0;    // [m/s] BlueSky's vsmin (min over the climb rates; see openap_perf.h)
  double axmax0 = 0;   // [m/s^2] acceleration limit before the first performance update
  // Mass, wing, engines
  double mass = 0;     // [kg]
  double sref = 0;     // [m^2]
  double thrust0 = 0;  // [N] total static maximum thrust (engines x max_thrust)
  double bpr = 0;      // [-] bypass ratio
  // Drag polar per configuration
  double cd0_clean = 0, k_clean = 0, cd0_to = 0, k_to = 0, cd0_ld = 0, k_ld = 0, cd_gear = 0;
};

class OpenapData {
 public:
  // Reads the folder (OpenAP's `data`). Error when it lacks the files above
  // or B744 (the fallback type) cannot be built; the message names the file.
  static Result<std::shared_ptr<const OpenapData>> load(const std::string& dir);

  // Data of `actype` (case-insensitive), B744 when unknown. Never null.
  const OpenapType* find(std::string_view actype) const;
  bool has(std::string_view actype) const;
  const std::string& dir() const { return dir_; }
  int size() const { return static_cast<int>(types_.size()); }
  // Every type the data knows, upper case, sorted, with its title (empty for a synonym).
  std::vector<std::pair<std::string, std::string>> titles() const;

 private:
  std::string dir_;
  std::map<std::string, OpenapType> types_;  // key: upper-case type as asked
  const OpenapType* fallback_ = nullptr;
};

// The data named by the environment variable SQUAWK_OPENAP, loaded once per
// process (null when unset; an unreadable folder is reported on stderr once
// and gives null). set_default_openap() replaces it (CLI flag --openap).
std::shared_ptr<const OpenapData> default_openap();
Status set_default_openap(const std::string& dir);

}  // namespace squawk::sim
