#pragma once
// The buildings as the LoS rule sees them, without ns-3: each a closed box
// [xmin, xmax] x [ymin, ymax] x [0, height]. The decision is the one ns-3.37's
// BuildingsChannelConditionModel makes for the same two points (a test holds them equal):
// - both ends outdoors: LoS unless the segment between them meets a box (boundary included);
// - both indoors: LoS only inside the same building;
// - one in, one out: NLoS.
#include <vector>

#include "common/scenario/scenario.h"

namespace rlpos {

class BuildingGeometry {
 public:
  explicit BuildingGeometry(const std::vector<BuildingSpec>& buildings);

  // The first building whose box holds `p`, or -1 (outdoors).
  int BuildingAt(const Vec3& p) const;
  // Line of sight between `a` and `b`. The arithmetic follows ns-3's to the last bit, which is
  // not symmetric in its rounding: give the sender first, as the channel does.
  bool Los(const Vec3& a, const Vec3& b) const;

 private:
  // A box as the segment test wants it: its centre and half sizes, computed once.
  struct CentredBox {
    Box bounds;
    Vec3 centre;
    Vec3 half;
  };
  static bool SegmentMeets(const CentredBox& box, const Vec3& a, const Vec3& b);
  std::vector<CentredBox> boxes_;
};

}  // namespace rlpos
