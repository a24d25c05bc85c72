#pragma once
// Buildings as exact ground shapes: a footprint is an outer ring with holes (courtyards), and a
// building is its footprint extruded between two heights. Points on a boundary count as inside,
// as ns-3's Box::IsInside and BuildingsChannelConditionModel count them for boxes.
#include <cstddef>
#include <string>
#include <vector>

#include "common/geometry/vec3.h"

namespace rlpos {

struct Point2 {
  double x = 0, y = 0;
};

// A closed ring given by its vertices in order, the first not repeated at the end. Either
// orientation. Edge i runs from vertex i to vertex i + 1 (the last one back to vertex 0).
using Ring = std::vector<Point2>;

struct Footprint {
  Ring outer;
  std::vector<Ring> holes;
};

struct Bounds2 {
  double xmin = 0, ymin = 0, xmax = 0, ymax = 0;
};

// The signed area (m^2), positive when counter-clockwise.
double SignedArea(const Ring& ring);
// The outer ring's area less its holes'.
double Area(const Footprint& footprint);
// The smallest rectangle holding the ring (all zero for an empty ring).
Bounds2 BoundsOf(const Ring& ring);

// Why `ring` is not a simple polygon, in a few words, or "" when it is: "vertex 2 is not a finite
// point", "fewer than 3 distinct points", "vertices 1 and 4 coincide", "edges 3 and 4 overlap"
// (one doubles back along the other), "edges 2 and 5 cross" (or "touch"), "zero area". Three or
// more vertices in a line are fine.
std::string RingDefect(const Ring& ring);
// Why hole `hole` of `footprint` does not fit, or "": its RingDefect, "reaches outside the outer
// ring", "overlaps hole <k>" (an earlier one). Touching the outer ring or another hole is fine.
std::string HoleDefect(const Footprint& footprint, std::size_t hole);
// Why `footprint` is not a valid polygon ("outer ring: <RingDefect>", "hole <k>: <HoleDefect>",
// "its holes leave no area"), or "". A hole may touch the outer ring (a clipped courtyard).
std::string FootprintDefect(const Footprint& footprint);

// Inside the outer ring and not strictly inside a hole; the boundary counts as inside. (Where a
// clipped courtyard touches the outer ring, the shared stretch counts as inside too.)
bool Contains(const Footprint& footprint, const Point2& p);
// The closed 2-D segment [a, b] meets the closed region of `footprint`.
bool SegmentMeets(const Footprint& footprint, const Point2& a, const Point2& b);
// The part of the 3-D segment [a, b] between heights zmin and zmax, in the plane: [from, to], or
// false when it has none. An end of [a, b] keeps its own coordinates, so that no rounding moves
// it. For a segment that is not vertical (a and b differ in x or y).
bool HeightSlice(const Vec3& a, const Vec3& b, double zmin, double zmax, Point2& from, Point2& to);
// The closed 3-D segment [a, b] meets the prism footprint x [zmin, zmax]: the segment is cut to
// the height range (HeightSlice), and that part tested in the plane (a vertical segment is a
// point test).
bool SegmentMeetsPrism(const Footprint& footprint, double zmin, double zmax, const Vec3& a,
                       const Vec3& b);

// The interiors of two valid footprints share an area deeper than `tolerance` (m): a point of
// one's boundary (a vertex, or the middle of a stretch between two meetings with the other's
// boundary) lies inside the other farther than `tolerance` from its boundary, or the two are the
// same region. Touching, and overlaps thinner than `tolerance` everywhere, are not overlaps.
bool InteriorsOverlap(const Footprint& a, const Footprint& b, double tolerance);

// The part of a valid `footprint` inside the rectangle, as pieces whose rings are simple (none
// when it lies outside). The outer ring is cut by each side of the rectangle in turn and may fall
// into several pieces; holes inside are kept, holes outside dropped, and a hole the rectangle
// cuts is cut too, so that it then touches its piece's outer ring along the rectangle's side.
std::vector<Footprint> ClipToRectangle(const Footprint& footprint, const Bounds2& rectangle);

}  // namespace rlpos
