#pragma once
// The obstacles of a venue and the one line-of-sight rule every part of RLpos uses. A solid is an
// axis-aligned box or a footprint extruded between two heights; the boundary counts as inside.
// The decision is the one ns-3.37's BuildingsChannelConditionModel makes for the same two points:
// - both ends outdoors: LoS unless the closed segment between them meets a solid;
// - both indoors: LoS only inside the same solid;
// - one in, one out: NLoS.
// For boxes the arithmetic is ns-3's to the last bit (tests hold it equal to ns-3); a uniform
// grid over the solids keeps a query's cost flat in their number, with the answers of a scan
// over all of them. Const queries are safe from several threads.
#include <cstddef>
#include <vector>

#include "common/geometry/footprint.h"
#include "common/geometry/solid_grid.h"
#include "common/geometry/vec3.h"

namespace rlpos {

struct Solid {
  // A box solid's box; for a prism, its bounding box (z: its heights).
  Box box;
  // Empty outer ring: a box solid.
  Footprint footprint;

  static Solid OfBox(const Box& box);
  // `footprint` (valid: FootprintDefect) between heights zmin < zmax.
  static Solid Prism(Footprint footprint, double zmin, double zmax);
  bool IsBox() const { return footprint.outer.empty(); }
};

class Obstacles {
 public:
  Obstacles() = default;
  explicit Obstacles(std::vector<Solid> solids);

  std::size_t size() const { return solids_.size(); }
  const Solid& solid(std::size_t i) const { return solids_[i].solid; }

  // The first solid holding `p`, or -1 (outdoors).
  int SolidAt(const Vec3& p) const;
  // The first solid whose ground shape holds (x, y), whatever its heights, or -1.
  int FootprintAt(double x, double y) const;
  // The closed segment [a, b] meets a solid.
  bool Blocked(const Vec3& a, const Vec3& b) const;
  // Line of sight between `a` and `b`, by the rule above. ns-3's arithmetic is not symmetric in
  // its rounding: give the sender first, as the channel does.
  bool Los(const Vec3& a, const Vec3& b) const;

  // One solid's own tests, which the queries above run on the solids the grid names.
  bool Holds(std::size_t i, const Vec3& p) const;
  bool HoldsGround(std::size_t i, double x, double y) const;
  bool Meets(std::size_t i, const Vec3& a, const Vec3& b) const;

 private:
  struct Entry {
    Solid solid;
    // A box as ns-3's segment test wants it: its centre and half sizes, computed once.
    Vec3 centre, half;
    // A prism: the bounds of all its rings (holes too), for the shortcut of Meets.
    Bounds2 rings;
  };
  static bool BoxMeets(const Entry& e, const Vec3& a, const Vec3& b);
  std::vector<Entry> solids_;
  SolidGrid grid_;
};

}  // namespace rlpos
