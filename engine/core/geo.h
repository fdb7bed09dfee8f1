// Geodesy used by the simulator and the environments.
//
// kwik*: BlueSky's flat-earth approximations (bluesky/tools/geo/_geo.py), used
// for conflict detection and observations so numbers match BlueSky:
//   kwikqdrdist: equirectangular with R = 6371000 m, mean-latitude cosine.
//   kwikpos: 60 NM per degree of latitude, longitude scaled by 1/cos(lat1).
// gc_*: spherical great-circle formulas with R = 6371 km (BlueSky-Gym's
// get_point_at_distance).
// Angles in degrees at this interface; distances as named in each function.
#pragma once

namespace squawk::geo {

struct QdrDist {
  double qdr_deg;  // [deg] bearing from point a to point b, in [0, 360)
  double dist_nm;  // [NM]
};
struct LatLon {
  double lat_deg;  // [deg]
  double lon_deg;  // [deg]
};

QdrDist kwikqdrdist(double lata, double lona, double latb, double lonb);
double kwikdist_nm(double lata, double lona, double latb, double lonb);
LatLon kwikpos(double lat, double lon, double qdr_deg, double dist_nm);
// BlueSky's qdrdist: bearing on the sphere and haversine distance with the
// WGS-84 local radius at the mean latitude (same hemisphere) or a
// latitude-weighted radius (crossing the equator). What BlueSky's autopilot
// (LNAV) uses for the active waypoint.
QdrDist qdrdist(double lata, double lona, double latb, double lonb);
// A latitude with its sine and cosine, for callers that keep them: qdrdist
// on LatTrig{lat * kDeg, sin, cos} of both points equals qdrdist on the
// latitudes bit for bit.
struct LatTrig {
  double rad = 0.0;  // [rad] latitude
  double sin = 0.0;  // [-] sin(rad)
  double cos = 1.0;  // [-] cos(rad)
};
LatTrig lat_trig(double lat_deg);
QdrDist qdrdist(const LatTrig& a, double lona, const LatTrig& b, double lonb);
// qdrdist of n pairs of points a[k], b[k] given as arrays: latitudes la, lb
// [rad] with their sines sa, sb and cosines ca, cb, longitudes lona, lonb
// [deg]; writes qdr_deg[k] and dist_nm[k]. Its sin, cos and atan2 go through
// vmath (libmvec in AVX2 builds: within a few ulp of qdrdist, not
// bit-identical; std:: elsewhere: equal to qdrdist bit for bit).
struct QdrDistArrays {
  const double *la, *sa, *ca, *lona;
  const double *lb, *sb, *cb, *lonb;
  double *qdr_deg, *dist_nm;
};
void qdrdist_n(const QdrDistArrays& p, int n);

// Great-circle destination from (lat, lon) along bearing for dist_m metres.
LatLon gc_destination(double lat, double lon, double bearing_deg, double dist_m);
// Great-circle (haversine) distance [m] and initial bearing [deg, 0..360).
double gc_distance_m(double lata, double lona, double latb, double lonb);
double gc_bearing_deg(double lata, double lona, double latb, double lonb);

// Wraps an angle [deg] into [0, 360).
double wrap360(double deg);
// Wraps an angle [deg] into (-180, 180].
double wrap180(double deg);
// BlueSky-Gym's bound_angle_positive_negative_180: wraps only once
// (a > 180 -> a - 360, a < -180 -> a + 360), as the gym observation does.
double gym_wrap180(double deg);

}  // namespace squawk::geo
