// ISA atmosphere and airspeed conversions, following BlueSky's tools/aero.py
// (troposphere lapse rate to 11 km, isothermal stratosphere above; compressible
// CAS <-> TAS through impact pressure).
//
// Contract: altitudes [m] above mean sea level, speeds [m/s], Mach
// dimensionless. All functions are pure and total for finite input; negative
// altitudes extrapolate the troposphere formula, as BlueSky does.
#pragma once

namespace squawk::sim {

inline constexpr double kP0 = 101325.0;      // [Pa] sea-level pressure
inline constexpr double kRho0 = 1.225;       // [kg/m^3] sea-level density
inline constexpr double kT0 = 288.15;        // [K] sea-level temperature
inline constexpr double kRGas = 287.05287;   // [J/(kg K)] specific gas constant of air
inline constexpr double kGamma = 1.40;       // [-] ratio of specific heats
inline constexpr double kLapse = -0.0065;    // [K/m] troposphere lapse rate
inline constexpr double kTropopause = 11000.0;  // [m]
// Speeds strictly between 0.1 and this value are read as Mach, others as CAS
// [m/s] (BlueSky's casmach_thr).
inline constexpr double kCasMachThreshold = 2.0;

struct Atmos {
  double p;     // [Pa] static pressure
  double rho;   // [kg/m^3] density
  double temp;  // [K] temperature
};

Atmos isa(double alt_m);
// BlueSky's scalar atmos() (tools/aero.py): the layered ISA table to 86 852 m,
// altitude clipped to [0, 86 852] m, pressure from each layer's exact
// exponent. isa() above is BlueSky's vectorised vatmos, whose troposphere
// density exponent is rounded; the two differ by about 1e-5 relative. BlueSky
// uses this one where it converts a single speed (creconfs' tas2cas).
Atmos isa_layered(double alt_m);
double isa_temperature(double alt_m);   // [K]
double isa_pressure(double alt_m);      // [Pa]
double isa_density(double alt_m);       // [kg/m^3]
double speed_of_sound(double alt_m);    // [m/s]
double speed_of_sound(const Atmos& a);  // [m/s]

double tas_to_cas(double tas, double alt_m);    // [m/s] -> [m/s]; sign kept
double cas_to_tas(double cas, double alt_m);    // [m/s] -> [m/s]; sign kept
// The same with the atmosphere at the altitude already computed (hot path).
double tas_to_cas(double tas, const Atmos& a);
double cas_to_tas(double cas, const Atmos& a);
double tas_to_mach(double tas, double alt_m);   // [m/s] -> [-]
double mach_to_tas(double mach, double alt_m);  // [-] -> [m/s]
double cas_to_mach(double cas, double alt_m);
double mach_to_cas(double mach, double alt_m);

// True when `spd` is read as a Mach number (0.1 < spd < kCasMachThreshold).
bool is_mach(double spd);

struct AirSpeeds {
  double tas;   // [m/s]
  double cas;   // [m/s]
  double mach;  // [-]
};
// BlueSky's vcasormach: `spd` is a Mach number when is_mach(spd), else CAS [m/s].
AirSpeeds casormach(double spd, double alt_m);
// The TAS [m/s] that `spd` (CAS [m/s] or Mach, as above) means at alt_m.
double casormach_to_tas(double spd, double alt_m);

}  // namespace squawk::sim
