// The local frame against the geodesic distance on the WGS84 ellipsoid (Vincenty's inverse
// formula, to a tenth of a millimetre), and its inverse.
#include "common/scenario_import/local_projection.h"

#include <gtest/gtest.h>

#include <cmath>

namespace rlpos {
namespace {

constexpr double kPi = 3.14159265358979323846;

// Vincenty (1975): the geodesic distance (m) between two points of the ellipsoid.
double GeodesicDistance(const LonLat& p1, const LonLat& p2) {
  const double a = kWgs84A, f = kWgs84F, b = a * (1 - f);
  const double rad = kPi / 180;
  const double l = (p2.lon - p1.lon) * rad;
  const double u1 = std::atan((1 - f) * std::tan(p1.lat * rad));
  const double u2 = std::atan((1 - f) * std::tan(p2.lat * rad));
  const double su1 = std::sin(u1), cu1 = std::cos(u1), su2 = std::sin(u2), cu2 = std::cos(u2);
  double lambda = l, sigma = 0, ss = 0, cs = 0, c2a = 0, c2sm = 0;
  for (int i = 0; i < 100; ++i) {
    const double sl = std::sin(lambda), cl = std::cos(lambda);
    ss = std::hypot(cu2 * sl, cu1 * su2 - su1 * cu2 * cl);
    cs = su1 * su2 + cu1 * cu2 * cl;
    sigma = std::atan2(ss, cs);
    const double sa = cu1 * cu2 * sl / ss;
    c2a = 1 - sa * sa;
    c2sm = cs - 2 * su1 * su2 / c2a;
    const double c = f / 16 * c2a * (4 + f * (4 - 3 * c2a));
    const double previous = lambda;
    lambda = l + (1 - c) * f * sa * (sigma + c * ss * (c2sm + c * cs * (-1 + 2 * c2sm * c2sm)));
    if (std::fabs(lambda - previous) < 1e-13)
      break;
  }
  const double usq = c2a * (a * a - b * b) / (b * b);
  const double ka = 1 + usq / 16384 * (4096 + usq * (-768 + usq * (320 - 175 * usq)));
  const double kb = usq / 1024 * (256 + usq * (-128 + usq * (74 - 47 * usq)));
  const double ds = kb * ss *
                    (c2sm + kb / 4 *
                                (cs * (-1 + 2 * c2sm * c2sm) -
                                 kb / 6 * c2sm * (-3 + 4 * ss * ss) * (-3 + 4 * c2sm * c2sm)));
  return b * ka * (sigma - ds);
}

// Points on a circle of 1 km about the centre, paired across it (2 km apart) and with their
// neighbours, plus the centre: the frame's distances against the geodesic's.
double WorstError(const LonLat& centre) {
  const LocalProjection projection(centre);
  std::vector<Point2> local;
  for (int k = 0; k < 16; ++k) {
    const double angle = 2 * kPi * k / 16;
    local.push_back({1000 * std::cos(angle), 1000 * std::sin(angle)});
  }
  local.push_back({0, 0});
  double worst = 0;
  for (std::size_t i = 0; i < local.size(); ++i) {
    for (std::size_t j = i + 1; j < local.size(); ++j) {
      const LonLat a = projection.Inverse(local[i]), b = projection.Inverse(local[j]);
      const Point2 pa = projection.Forward(a), pb = projection.Forward(b);
      const double plane = std::hypot(pa.x - pb.x, pa.y - pb.y);
      worst = std::max(worst, std::fabs(plane - GeodesicDistance(a, b)));
    }
  }
  return worst;
}

TEST(LocalProjection, ErrorOver2KmAgainstGeodesic) {
  // Helsinki (8 micrometres, the header's figure), the equator and further north: under 0.1 mm
  // over 2 km. A plate carree scaled at the centre would be off by 0.3 m at Helsinki.
  const double helsinki = WorstError({24.9521, 60.1695});
  EXPECT_LT(helsinki, 2e-5);
  EXPECT_LT(WorstError({0, 0}), 1e-4);
  EXPECT_LT(WorstError({-70, 78}), 1e-4);
  // The reference itself: a degree of latitude at the equator, 110574.4 m.
  EXPECT_NEAR(GeodesicDistance({0, 0}, {0, 1}), 110574.4, 0.1);
  RecordProperty("helsinki_error_m", std::to_string(helsinki));
}

TEST(LocalProjection, AxesPointEastAndNorth) {
  const LocalProjection projection({25.0, 60.0});
  const Point2 east = projection.Forward({25.001, 60.0});
  const Point2 north = projection.Forward({25.0, 60.001});
  EXPECT_NEAR(east.x, 55.8, 0.1);  // a thousandth of a degree of longitude at 60 N
  EXPECT_NEAR(east.y, 0, 1e-3);
  EXPECT_NEAR(north.y, 111.4, 0.1);
  EXPECT_NEAR(north.x, 0, 1e-9);
}

TEST(LocalProjection, InverseUndoesForward) {
  const LocalProjection projection({24.9521, 60.1695});
  for (const Point2 p : {Point2{0, 0}, Point2{1500, -800}, Point2{-2000, 2000}}) {
    const Point2 back = projection.Forward(projection.Inverse(p));
    EXPECT_NEAR(back.x, p.x, 1e-6);
    EXPECT_NEAR(back.y, p.y, 1e-6);
  }
}

}  // namespace
}  // namespace rlpos
