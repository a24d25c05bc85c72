#pragma once
// Footprints the geometry tests share, and a seeded random simple polygon.
#include <cmath>
#include <random>

#include "common/geometry/footprint.h"

namespace rlpos {
namespace test_shapes {

// [x0, x1] x [y0, y1], counter-clockwise.
inline Ring Rect(double x0, double y0, double x1, double y1) {
  return {{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}};
}
inline Footprint Square(double x0, double y0, double side) {
  return {Rect(x0, y0, x0 + side, y0 + side), {}};
}
// An L: [0, 10] x [0, 4] and [0, 4] x [4, 10].
inline Ring LShape() {
  return {{0, 0}, {10, 0}, {10, 4}, {4, 4}, {4, 10}, {0, 10}};
}
// A U open to +y: [0, 10] x [0, 10] less [3, 7] x [3, 10].
inline Ring UShape() {
  return {{0, 0}, {10, 0}, {10, 10}, {7, 10}, {7, 3}, {3, 3}, {3, 10}, {0, 10}};
}
// [0, 20]^2 with the courtyard [5, 15]^2 (clockwise, as GeoJSON writes holes).
inline Footprint Courtyard() {
  return {Rect(0, 0, 20, 20), {{{5, 5}, {5, 15}, {15, 15}, {15, 5}}}};
}

// A star-shaped (hence simple) polygon about (cx, cy): n vertices at increasing angles, radii
// in [r_min, r_max].
inline Ring RandomStar(std::mt19937_64& rng, double cx, double cy, double r_min, double r_max,
                       int n) {
  std::uniform_real_distribution<double> radius(r_min, r_max);
  std::uniform_real_distribution<double> jitter(0.1, 0.9);
  Ring ring;
  const double step = 2 * M_PI / n;
  for (int k = 0; k < n; ++k) {
    const double angle = (k + jitter(rng)) * step;
    const double r = radius(rng);
    ring.push_back({cx + r * std::cos(angle), cy + r * std::sin(angle)});
  }
  return ring;
}

}  // namespace test_shapes
}  // namespace rlpos
