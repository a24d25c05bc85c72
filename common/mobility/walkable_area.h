#pragma once
// Where a UE may walk: the venue's ground minus every building's ground shape (walls included;
// a box's rectangle or a footprint, holes open), and which straight legs stay in it.
#include <vector>

#include "common/geometry/footprint.h"
#include "common/scenario/scenario.h"

namespace rlpos {

class WalkableArea {
 public:
  explicit WalkableArea(const Scenario& scenario);

  double width() const { return width_; }
  double depth() const { return depth_; }
  // (x, y) is in the venue and off every footprint.
  bool Contains(double x, double y) const;
  // The straight leg from a to b (x, y only) touches no footprint and stays in the venue.
  bool LegIsClear(const Vec3& a, const Vec3& b) const;

 private:
  struct Shape {
    Footprint ground;
    Bounds2 bounds;  // checked first: most shapes are far from a given point or leg
  };
  double width_;
  double depth_;
  std::vector<Shape> shapes_;
};

}  // namespace rlpos
