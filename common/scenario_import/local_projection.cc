#include "common/scenario_import/local_projection.h"

#include <cmath>

namespace rlpos {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kRadians = kPi / 180.0;

struct Ecef {
  double x, y, z;
};

// A point of the ellipsoid's surface in Earth-centred, Earth-fixed coordinates.
Ecef ToEcef(const LonLat& p) {
  const double e2 = kWgs84F * (2 - kWgs84F);
  const double lat = p.lat * kRadians, lon = p.lon * kRadians;
  const double s = std::sin(lat), c = std::cos(lat);
  const double n = kWgs84A / std::sqrt(1 - e2 * s * s);
  return {n * c * std::cos(lon), n * c * std::sin(lon), n * (1 - e2) * s};
}

}  // namespace

LocalProjection::LocalProjection(const LonLat& origin) : origin_(origin) {
  const Ecef o = ToEcef(origin);
  x0_ = o.x;
  y0_ = o.y;
  z0_ = o.z;
  sin_lat_ = std::sin(origin.lat * kRadians);
  cos_lat_ = std::cos(origin.lat * kRadians);
  sin_lon_ = std::sin(origin.lon * kRadians);
  cos_lon_ = std::cos(origin.lon * kRadians);
  // The radii of curvature at the origin, for Inverse's first guess and its steps.
  const double e2 = kWgs84F * (2 - kWgs84F);
  const double w = std::sqrt(1 - e2 * sin_lat_ * sin_lat_);
  const double meridian = kWgs84A * (1 - e2) / (w * w * w);
  const double normal = kWgs84A / w;
  metres_per_degree_lat_ = meridian * kRadians;
  metres_per_degree_lon_ = normal * cos_lat_ * kRadians;
}

Point2 LocalProjection::Forward(const LonLat& p) const {
  const Ecef e = ToEcef(p);
  const double dx = e.x - x0_, dy = e.y - y0_, dz = e.z - z0_;
  const double east = -sin_lon_ * dx + cos_lon_ * dy;
  const double north = -sin_lat_ * cos_lon_ * dx - sin_lat_ * sin_lon_ * dy + cos_lat_ * dz;
  return {east, north};
}

LonLat LocalProjection::Inverse(const Point2& p) const {
  LonLat guess{origin_.lon + p.x / metres_per_degree_lon_,
               origin_.lat + p.y / metres_per_degree_lat_};
  // The frame is within a few parts per million of the local scale: each step gains about
  // five digits.
  for (int step = 0; step < 3; ++step) {
    const Point2 at = Forward(guess);
    guess.lon += (p.x - at.x) / metres_per_degree_lon_;
    guess.lat += (p.y - at.y) / metres_per_degree_lat_;
  }
  return guess;
}

}  // namespace rlpos
