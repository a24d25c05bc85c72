#pragma once
// Where a UE may walk: the venue's ground minus every building's footprint (walls included),
// and which straight legs stay in it.
#include <vector>

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
  struct Rectangle {
    double xmin, xmax, ymin, ymax;
  };
  double width_;
  double depth_;
  std::vector<Rectangle> footprints_;
};

}  // namespace rlpos
