#include "sim/atmosphere.h"

#include <algorithm>
#include <cmath>

namespace squawk::sim {

namespace {
constexpr double kTStrat = 216.65;            // [K] isothermal layer temperature
constexpr double kTropExp = 4.256848030018761;  // [-] -(g0 / (R L)) - 1 for the density ratio
constexpr double kStratScale = 6341.552161;   // [m] density scale height above the tropopause
}  // namespace

double isa_temperature(double alt_m) { return std::max(kT0 + kLapse * alt_m, kTStrat); }

double isa_density(double alt_m) {
  const double t = isa_temperature(alt_m);
  const double rho_trop = kRho0 * std::pow(t / kT0, kTropExp);
  const double above = std::max(0.0, alt_m - kTropopause);
  return rho_trop * std::exp(-above / kStratScale);
}

double isa_pressure(double alt_m) { return isa_density(alt_m) * kRGas * isa_temperature(alt_m); }

Atmos isa(double alt_m) {
  const double t = isa_temperature(alt_m);
  const double rho = isa_density(alt_m);
  return {rho * kRGas * t, rho, t};
}

Atmos isa_layered(double alt_m) {
  constexpr double kG0 = 9.80665;  // [m/s^2]
  constexpr double h0[] = {0.0, 11000., 20000., 32000., 47000., 51000., 71000., 86852.};           // [m]
  constexpr double p0[] = {101325., 22631.7009099, 5474.71768857, 867.974468302, 110.898214043,
                           66.939, 3.9564};                                                            // [Pa]
  constexpr double t0[] = {288.15, 216.65, 216.65, 228.65, 270.65, 270.65, 214.65};                 // [K]
  constexpr double lapse[] = {-0.0065, 0, 0.001, 0.0028, 0, -0.0028, -0.002};                        // [K/m]
  const double h = std::max(0.0, std::min(alt_m, h0[7]));
  int i = 0;
  while (h > h0[i + 1] && i < 6) ++i;
  double t, p;
  if (lapse[i] == 0) {
    t = t0[i];
    p = p0[i] * std::exp(-kG0 / (kRGas * t) * (h - h0[i]));
  } else {
    t = t0[i] + lapse[i] * (h - h0[i]);
    p = p0[i] * std::pow(t / t0[i], -kG0 / (lapse[i] * kRGas));
  }
  return {p, p / (kRGas * t), t};
}

double speed_of_sound(double alt_m) { return std::sqrt(kGamma * kRGas * isa_temperature(alt_m)); }
double speed_of_sound(const Atmos& a) { return std::sqrt(kGamma * kRGas * a.temp); }

namespace {
double pow3_5(double x) { return x * x * x * std::sqrt(x); }
}  // namespace

// Impact pressure qdyn = p ((1 + rho v^2 / (7 p))^3.5 - 1) at one density and
// pressure, inverted at the other.
double tas_to_cas(double tas, const Atmos& a) {
  const double qdyn = a.p * (pow3_5(1.0 + a.rho * tas * tas / (7.0 * a.p)) - 1.0);
  const double cas = std::sqrt(7.0 * kP0 / kRho0 * (std::pow(qdyn / kP0 + 1.0, 2.0 / 7.0) - 1.0));
  return tas < 0 ? -cas : cas;
}

double cas_to_tas(double cas, const Atmos& a) {
  const double qdyn = kP0 * (pow3_5(1.0 + kRho0 * cas * cas / (7.0 * kP0)) - 1.0);
  const double tas = std::sqrt(7.0 * a.p / a.rho * (std::pow(1.0 + qdyn / a.p, 2.0 / 7.0) - 1.0));
  return cas < 0 ? -tas : tas;
}

double tas_to_cas(double tas, double alt_m) { return tas_to_cas(tas, isa(alt_m)); }
double cas_to_tas(double cas, double alt_m) { return cas_to_tas(cas, isa(alt_m)); }

double tas_to_mach(double tas, double alt_m) { return tas / speed_of_sound(alt_m); }
double mach_to_tas(double mach, double alt_m) { return mach * speed_of_sound(alt_m); }
double cas_to_mach(double cas, double alt_m) { return tas_to_mach(cas_to_tas(cas, alt_m), alt_m); }
double mach_to_cas(double mach, double alt_m) { return tas_to_cas(mach_to_tas(mach, alt_m), alt_m); }

bool is_mach(double spd) { return spd > 0.1 && spd < kCasMachThreshold; }

AirSpeeds casormach(double spd, double alt_m) {
  if (is_mach(spd)) {
    const double tas = mach_to_tas(spd, alt_m);
    return {tas, tas_to_cas(tas, alt_m), spd};
  }
  const double tas = cas_to_tas(spd, alt_m);
  return {tas, spd, tas_to_mach(tas, alt_m)};
}

double casormach_to_tas(double spd, double alt_m) {
  return is_mach(spd) ? mach_to_tas(spd, alt_m) : cas_to_tas(spd, alt_m);
}

}  // namespace squawk::sim
