// Aviation units <-> SI. SI inside the engine; these convert at the edges.
// Constants follow BlueSky's tools/aero.py (docs/bluesky_facts.md §5).
#pragma once

namespace squawk::units {

inline constexpr double kPi = 3.14159265358979323846;
inline constexpr double kKt = 0.514444;        // [m/s] per knot
inline constexpr double kFt = 0.3048;          // [m] per foot
inline constexpr double kFpm = kFt / 60.0;     // [m/s] per foot/minute
inline constexpr double kNm = 1852.0;          // [m] per nautical mile
inline constexpr double kG0 = 9.80665;         // [m/s^2] standard gravity
inline constexpr double kREarth = 6371000.0;   // [m] earth radius (flat-earth and great circle)
inline constexpr double kDeg = kPi / 180.0;    // [rad] per degree

constexpr double kt_to_ms(double kt) { return kt * kKt; }
constexpr double ms_to_kt(double ms) { return ms / kKt; }
constexpr double ft_to_m(double ft) { return ft * kFt; }
constexpr double m_to_ft(double m) { return m / kFt; }
constexpr double nm_to_m(double nm) { return nm * kNm; }
constexpr double m_to_nm(double m) { return m / kNm; }
constexpr double fpm_to_ms(double fpm) { return fpm * kFpm; }
constexpr double ms_to_fpm(double ms) { return ms / kFpm; }
constexpr double fl_to_m(double fl) { return fl * 100.0 * kFt; }   // flight level -> [m]
constexpr double m_to_fl(double m) { return m / (100.0 * kFt); }
constexpr double deg_to_rad(double d) { return d * kDeg; }
constexpr double rad_to_deg(double r) { return r / kDeg; }

}  // namespace squawk::units
