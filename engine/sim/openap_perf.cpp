#include "sim/openap_perf.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/units.h"
#include "sim/atmosphere.h"

namespace squawk::sim {

namespace {
constexpr double kGroundAxmax = 2.0;  // [m/s^2] fixed-wing on the ground
constexpr double kMinAxmax = 0.5;     // [m/s^2] floor of the acceleration limit
constexpr double kLbf = 4.448;        // [N] per pound-force as the thrust model writes it

// OpenAP take-off thrust ratio (of the static maximum).
double takeoff_ratio(double bpr, double tas, double alt) {
  const double g0 = 0.0606 * bpr + 0.6337;
  const double mach = tas_to_mach(tas, alt);
  const double pp = isa_pressure(alt) / kP0;
  const double a = -0.4327 * pp * pp + 1.3855 * pp + 0.0472;
  const double z = 0.9106 * pp * pp * pp - 1.7736 * pp * pp + 1.8697 * pp;
  const double x = 0.1377 * pp * pp * pp - 0.4374 * pp * pp + 1.3003 * pp;
  return a - 0.377 * (1.0 + bpr) / std::sqrt((1.0 + 0.82 * bpr) * g0) * z * mach +
         (0.23 + 0.19 * std::sqrt(bpr)) * x * mach * mach;
}

// OpenAP in-flight maximum thrust ratio (of the static maximum thr0 [N]):
// three segments split at 10 000 and 35 000 ft, referenced to the thrust at
// the top of climb F35 = (200 + 0.2 thr0/lbf) lbf at Mach 0.8.
double inflight_ratio(double tas, double alt, double vs, double thr0) {
  const double roc = std::fabs(vs / units::kFpm);
  const double v = std::max(tas, 10.0);
  const double mach = tas_to_mach(v, alt);
  const double vcas = tas_to_cas(v, alt);
  const double p = isa_pressure(alt);
  static const double p10 = isa_pressure(10000.0 * units::kFt);
  static const double p35 = isa_pressure(35000.0 * units::kFt);
  static const double vcas_ref = mach_to_cas(0.8, 35000.0 * units::kFt);
  const double f35 = (200.0 + 0.2 * thr0 / kLbf) * kLbf;
  double ratio;
  if (alt > 35000.0 * units::kFt) {
    const double mr = mach / 0.8;
    ratio = (-0.4204 * mr + 1.0824) * std::log(p / p35) + std::pow(mr, -0.11);
  } else {
    const double vr = vcas / vcas_ref;
    const double a = std::pow(vr, -0.1);
    const double n = 2.667e-05 * roc + 0.8633;
    if (alt > 10000.0 * units::kFt) {
      ratio = a * std::pow(p / p35, -0.355 * vr + n);
    } else {
      const double f10 = f35 * a * std::pow(p10 / p35, -0.355 * vr + n);
      const double m = -1.2043e-1 * vr - 8.8889e-9 * roc * roc + 2.4444e-5 * roc + 4.7379e-1;
      ratio = m * (p / p35) + (f10 / f35 - m * (p10 / p35));
    }
  }
  return ratio * f35 / thr0;
}
}  // namespace

FlightPhase openap_phase(double alt, double vs) {
  const double h = alt / units::kFt, roc = vs / units::kFpm;
  FlightPhase ph = FlightPhase::kNA;
  if (h <= 75.0) ph = FlightPhase::kGround;
  if (h >= 75.0 && h <= 1000.0 && roc >= 150.0) ph = FlightPhase::kInitClimb;
  if (h >= 75.0 && h <= 1000.0 && roc <= -150.0) ph = FlightPhase::kApproach;
  if (h >= 1000.0 && roc >= 150.0) ph = FlightPhase::kClimb;
  if (h >= 1000.0 && roc <= -150.0) ph = FlightPhase::kDescent;
  if (h >= 10000.0 && roc <= 150.0 && roc >= -150.0) ph = FlightPhase::kCruise;
  return ph;
}

double openap_drag(const OpenapType& t, FlightPhase phase, double tas, double alt) {
  double cd0 = t.cd0_clean, k = t.k_clean;
  if (phase == FlightPhase::kGround) cd0 = t.cd0_to + t.cd_gear, k = t.k_to;
  else if (phase == FlightPhase::kInitClimb) cd0 = t.cd0_to, k = t.k_to;
  else if (phase == FlightPhase::kApproach) cd0 = t.cd0_ld, k = t.k_ld;
  const double q = 0.5 * isa_density(alt) * tas * tas * t.sref;
  if (!(q > 0.0)) return std::numeric_limits<double>::infinity();
  const double cl = t.mass * units::kG0 / q;
  return q * (cd0 + k * cl * cl);
}

double openap_max_thrust(const OpenapType& t, FlightPhase phase, double tas, double alt, double vs) {
  const double ratio = phase == FlightPhase::kGround ? takeoff_ratio(t.bpr, tas, alt)
                                                     : inflight_ratio(tas, alt, vs, t.thrust0);
  return ratio * t.thrust0;
}

void openap_update(const OpenapType& t, double tas, double vs, double alt, FlightPhase& phase, PerfLimits& lim) {
  phase = openap_phase(alt, vs);
  switch (phase) {
    case FlightPhase::kGround: lim.vmin = 0.0, lim.vmax = t.vmaxic; break;
    case FlightPhase::kApproach: lim.vmin = t.vminap, lim.vmax = t.vmaxap; break;
    default: lim.vmin = t.vminer, lim.vmax = t.vmaxer; break;
  }
  double ax = (openap_max_thrust(t, phase, tas, alt, vs) - openap_drag(t, phase, tas, alt)) / t.mass;
  if (phase == FlightPhase::kGround) ax = kGroundAxmax;
  lim.axmax = std::isfinite(ax) ? std::max(ax, kMinAxmax) : kMinAxmax;
}

double openap_limit_tas(const PerfLimits& lim, double intent_tas, double allow_alt) {
  const Atmos a = isa(allow_alt);
  const double cas = std::min(std::max(tas_to_cas(intent_tas, a), lim.vmin), lim.vmax);
  const double tas = cas_to_tas(cas, a);
  const double tas_mmo = lim.mmo * speed_of_sound(a);
  return tas > tas_mmo ? tas_mmo : tas;
}

double openap_limit_vs(const OpenapType& t, const PerfLimits& lim, FlightPhase phase, double intent_vs,
                       double ax, double tas) {
  double vs = intent_vs;
  if (intent_vs > lim.vsmax) vs = (1.0 - ax / lim.axmax) * lim.vsmax;
  if (phase == FlightPhase::kGround && tas < t.vminto) vs = 0.0;
  return vs;
}

}  // namespace squawk::sim
