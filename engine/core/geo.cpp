#include "core/geo.h"

#include <algorithm>
#include <cmath>

#include "core/units.h"
#include "core/vmath.h"

namespace squawk::geo {

using units::kDeg;
using units::kNm;
using units::kREarth;

namespace {
// Python's floor-mod for the longitude wrap ((x + 180) % 360 - 180).
// (fmod(a, m) is a itself when |a| < m: the common case skips the call.)
double pymod(double a, double m) {
  if (std::fabs(a) < m) return a < 0 ? a + m : a;
  double r = std::fmod(a, m);
  return (r < 0) ? r + m : r;
}
}  // namespace

QdrDist kwikqdrdist(double lata, double lona, double latb, double lonb) {
  const double dlat = (latb - lata) * kDeg;
  const double dlon = (pymod(lonb - lona + 180.0, 360.0) - 180.0) * kDeg;
  const double cavelat = std::cos((lata + latb) * kDeg * 0.5);
  const double dangle = std::sqrt(dlat * dlat + dlon * dlon * cavelat * cavelat);
  const double dist = kREarth * dangle / kNm;
  const double qdr = pymod(std::atan2(dlon * cavelat, dlat) / kDeg, 360.0);
  return {qdr, dist};
}

namespace {
// WGS-84 local earth radius [m] (BlueSky's rwgs84).
double rwgs84(double sinlat, double coslat) {
  constexpr double a = 6378137.0, b = 6356752.314245;  // [m] WGS-84 semi-axes
  const double a2 = a * a, b2 = b * b, s2 = sinlat * sinlat, c2 = coslat * coslat;
  return std::sqrt((a2 * a2 * c2 + b2 * b2 * s2) / (a2 * c2 + b2 * s2));
}
}  // namespace

LatTrig lat_trig(double lat_deg) {
  const double r = lat_deg * kDeg;
  return {r, std::sin(r), std::cos(r)};
}

QdrDist qdrdist(double lata, double lona, double latb, double lonb) {
  return qdrdist(lat_trig(lata), lona, lat_trig(latb), lonb);
}

QdrDist qdrdist(const LatTrig& pa, double lona, const LatTrig& pb, double lonb) {
  constexpr double a = 6378137.0;
  const double la = pa.rad, lb = pb.rad, dlon = (lonb - lona) * kDeg;
  const double sa = pa.sin, ca = pa.cos, sb = pb.sin, cb = pb.cos;
  double r;
  if (la * lb >= 0.0) {
    const double m = 0.5 * (la + lb);
    r = rwgs84(std::sin(m), std::cos(m));
  } else {
    r = 0.5 * (std::fabs(la) * (rwgs84(sa, ca) + a) + std::fabs(lb) * (rwgs84(sb, cb) + a)) /
        (std::fabs(la) + std::fabs(lb));
  }
  const double s1 = std::sin(0.5 * (lb - la)), s2 = std::sin(0.5 * dlon);
  const double root = s1 * s1 + ca * cb * s2 * s2;
  const double d = 2.0 * r * std::atan2(std::sqrt(root), std::sqrt(1.0 - root));
  const double qdr = std::atan2(std::sin(dlon) * cb, sb * ca - sa * cb * std::cos(dlon)) / kDeg;
  return {pymod(qdr, 360.0), d / kNm};
}

void qdrdist_n(const QdrDistArrays& p, int n) {
  constexpr double a = 6378137.0;
  constexpr int kBlock = 64;  // elements per pass through the scratch arrays below
  double m[kBlock], h1[kBlock], dl[kBlock], h2[kBlock];
  double sm[kBlock], cm[kBlock], s1[kBlock], s2[kBlock], sdl[kBlock], cdl[kBlock];
  double y1[kBlock], x1[kBlock], y2[kBlock], x2[kBlock], r[kBlock];
  for (int o = 0; o < n; o += kBlock) {
    const int b = std::min(kBlock, n - o);
    const double *la = p.la + o, *lb = p.lb + o, *sa = p.sa + o, *ca = p.ca + o, *sb = p.sb + o, *cb = p.cb + o;
    for (int k = 0; k < b; ++k) {
      m[k] = 0.5 * (la[k] + lb[k]);
      h1[k] = 0.5 * (lb[k] - la[k]);
      dl[k] = (p.lonb[o + k] - p.lona[o + k]) * kDeg;
      h2[k] = 0.5 * dl[k];
    }
    vmath::sin(m, 1.0, sm, b);
    vmath::cos(m, 1.0, cm, b);
    vmath::sin(h1, 1.0, s1, b);
    vmath::sin(h2, 1.0, s2, b);
    vmath::sin(dl, 1.0, sdl, b);
    vmath::cos(dl, 1.0, cdl, b);
    for (int k = 0; k < b; ++k) {
      if (la[k] * lb[k] >= 0.0) {
        r[k] = rwgs84(sm[k], cm[k]);
      } else {
        r[k] = 0.5 * (std::fabs(la[k]) * (rwgs84(sa[k], ca[k]) + a) + std::fabs(lb[k]) * (rwgs84(sb[k], cb[k]) + a)) /
               (std::fabs(la[k]) + std::fabs(lb[k]));
      }
      const double root = s1[k] * s1[k] + ca[k] * cb[k] * s2[k] * s2[k];
      y1[k] = std::sqrt(root);
      x1[k] = std::sqrt(1.0 - root);
      y2[k] = sdl[k] * cb[k];
      x2[k] = sb[k] * ca[k] - sa[k] * cb[k] * cdl[k];
    }
    vmath::atan2(y1, x1, y1, b);
    vmath::atan2(y2, x2, y2, b);
    for (int k = 0; k < b; ++k) {
      p.dist_nm[o + k] = 2.0 * r[k] * y1[k] / kNm;
      p.qdr_deg[o + k] = pymod(y2[k] / kDeg, 360.0);
    }
  }
}

double kwikdist_nm(double lata, double lona, double latb, double lonb) {
  return kwikqdrdist(lata, lona, latb, lonb).dist_nm;
}

LatLon kwikpos(double lat, double lon, double qdr_deg, double dist_nm) {
  const double dx = dist_nm * std::sin(qdr_deg * kDeg);
  const double dy = dist_nm * std::cos(qdr_deg * kDeg);
  const double dlat = dy / 60.0;
  const double dlon = dx / std::max(0.01, 60.0 * std::cos(lat * kDeg));
  return {lat + dlat, pymod(lon + dlon + 180.0, 360.0) - 180.0};
}

LatLon gc_destination(double lat, double lon, double bearing_deg, double dist_m) {
  const double R = kREarth;
  const double phi1 = lat * kDeg, lam1 = lon * kDeg, brg = bearing_deg * kDeg;
  const double d = dist_m / R;
  const double phi2 = std::asin(std::sin(phi1) * std::cos(d) + std::cos(phi1) * std::sin(d) * std::cos(brg));
  const double lam2 = lam1 + std::atan2(std::sin(brg) * std::sin(d) * std::cos(phi1),
                                        std::cos(d) - std::sin(phi1) * std::sin(phi2));
  return {phi2 / kDeg, lam2 / kDeg};
}

double gc_distance_m(double lata, double lona, double latb, double lonb) {
  const double p1 = lata * kDeg, p2 = latb * kDeg;
  const double dp = p2 - p1, dl = (lonb - lona) * kDeg;
  const double a = std::sin(dp / 2) * std::sin(dp / 2) +
                   std::cos(p1) * std::cos(p2) * std::sin(dl / 2) * std::sin(dl / 2);
  return 2.0 * kREarth * std::atan2(std::sqrt(a), std::sqrt(std::max(0.0, 1.0 - a)));
}

double gc_bearing_deg(double lata, double lona, double latb, double lonb) {
  const double p1 = lata * kDeg, p2 = latb * kDeg, dl = (lonb - lona) * kDeg;
  const double y = std::sin(dl) * std::cos(p2);
  const double x = std::cos(p1) * std::sin(p2) - std::sin(p1) * std::cos(p2) * std::cos(dl);
  return wrap360(std::atan2(y, x) / kDeg);
}

double wrap360(double deg) {
  double r = std::fabs(deg) < 360.0 ? deg : std::fmod(deg, 360.0);  // the same value, without the call
  if (r < 0) r += 360.0;
  if (r >= 360.0) r -= 360.0;  // fmod of -tiny + 360 rounds to 360
  return r;
}

double wrap180(double deg) {
  double r = wrap360(deg);
  return r > 180.0 ? r - 360.0 : r;
}

double gym_wrap180(double deg) {
  if (deg > 180.0) return -(360.0 - deg);
  if (deg < -180.0) return 360.0 + deg;
  return deg;
}

}  // namespace squawk::geo
