#include <doctest/doctest.h>

#include <cmath>
#include <string>

#include "core/units.h"
#include "sim/atmosphere.h"
#include "sim/performance.h"

using namespace squawk;
using namespace squawk::sim;

TEST_CASE("ISA matches the standard atmosphere tables") {
  // ICAO standard atmosphere: sea level and tropopause values.
  CHECK(isa_temperature(0) == doctest::Approx(288.15));
  CHECK(isa_pressure(0) == doctest::Approx(101325.0).epsilon(1e-4));
  CHECK(isa_density(0) == doctest::Approx(1.225));
  CHECK(isa_temperature(11000) == doctest::Approx(216.65));
  CHECK(isa_pressure(11000) == doctest::Approx(22632.0).epsilon(1e-3));
  CHECK(isa_density(11000) == doctest::Approx(0.36392).epsilon(1e-3));
  // Stratosphere (isothermal): 20 km table value 5474.9 Pa.
  CHECK(isa_temperature(15000) == doctest::Approx(216.65));
  CHECK(isa_pressure(20000) == doctest::Approx(5474.9).epsilon(2e-3));
  CHECK(speed_of_sound(0) == doctest::Approx(340.294).epsilon(1e-4));
  const Atmos a = isa(5000);
  CHECK(a.p == doctest::Approx(54048.0).epsilon(1e-3));
  CHECK(a.rho == doctest::Approx(isa_density(5000)));
}

TEST_CASE("CAS, TAS and Mach conversions") {
  // At sea level CAS equals TAS.
  CHECK(cas_to_tas(150.0, 0.0) == doctest::Approx(150.0).epsilon(1e-9));
  CHECK(tas_to_cas(150.0, 0.0) == doctest::Approx(150.0).epsilon(1e-9));
  // Round trips at altitude.
  for (double h : {0.0, 3000.0, 9000.0, 11000.0, 13000.0})
    for (double v : {50.0, 128.6, 250.0}) CHECK(tas_to_cas(cas_to_tas(v, h), h) == doctest::Approx(v).epsilon(1e-10));
  // 250 kt CAS at 10 000 ft is about 288 kt TAS (E6B / standard tables).
  CHECK(units::ms_to_kt(cas_to_tas(units::kt_to_ms(250), units::ft_to_m(10000))) ==
        doctest::Approx(288.0).epsilon(0.005));
  // Independent route for M0.78 at FL350: barometric pressure p0 (T/T0)^5.25588
  // and the isentropic impact pressure in Mach form (gives 264.4 kt CAS);
  // BlueSky's density exponent differs in the 4th digit, hence 5e-4.
  const double h = units::fl_to_m(350);
  const double t = 288.15 - 0.0065 * h;
  const double a = std::sqrt(1.4 * 287.05287 * t);
  const double p = 101325.0 * std::pow(t / 288.15, 5.25588);
  const double qc = p * (std::pow(1.0 + 0.2 * 0.78 * 0.78, 3.5) - 1.0);
  const double cas_ref = 340.294 * std::sqrt(5.0 * (std::pow(qc / 101325.0 + 1.0, 2.0 / 7.0) - 1.0));
  CHECK(mach_to_tas(0.78, h) == doctest::Approx(0.78 * a));
  CHECK(mach_to_cas(0.78, h) == doctest::Approx(cas_ref).epsilon(5e-4));
  CHECK(tas_to_mach(mach_to_tas(0.78, h), h) == doctest::Approx(0.78));
  CHECK(cas_to_tas(-100.0, 5000.0) == doctest::Approx(-cas_to_tas(100.0, 5000.0)));
}

TEST_CASE("vcasormach reads values between 0.1 and 2 as Mach") {
  CHECK(is_mach(0.8));
  CHECK(!is_mach(150.0));
  CHECK(!is_mach(0.05));
  CHECK(!is_mach(2.0));
  const AirSpeeds m = casormach(0.8, 10000.0);
  CHECK(m.mach == 0.8);
  CHECK(m.tas == doctest::Approx(0.8 * speed_of_sound(10000.0)));
  const AirSpeeds c = casormach(150.0, 0.0);
  CHECK(c.cas == 150.0);
  CHECK(c.tas == doctest::Approx(150.0));
  CHECK(casormach_to_tas(150.0, 3000.0) == doctest::Approx(cas_to_tas(150.0, 3000.0)));
}

TEST_CASE("performance classes by ICAO type") {
  CHECK(perf_class_of("A320") == PerfClass::kJet);
  CHECK(perf_class_of("b744") == PerfClass::kJet);
  CHECK(perf_class_of("AT72") == PerfClass::kTurboprop);
  CHECK(perf_class_of(" c172 ") == PerfClass::kPiston);
  CHECK(perf_class_of("EC35") == PerfClass::kHelicopter);
  CHECK(perf_class_of("ZZZZ") == PerfClass::kJet);
  for (PerfClass c : {PerfClass::kJet, PerfClass::kTurboprop, PerfClass::kPiston, PerfClass::kHelicopter}) {
    const PerfLimits& p = perf_limits(c);
    CHECK(p.vmin < p.vmax);
    CHECK(p.vsmin == -p.vsmax);
    CHECK(p.axmax > 0);
  }
  CHECK(std::string(perf_class_name(PerfClass::kPiston)) == "piston");
}
