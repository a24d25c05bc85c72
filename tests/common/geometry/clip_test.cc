// ClipToRectangle: the pieces are valid footprints and cover exactly the part of the footprint
// inside the rectangle, point by point and in area.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

#include "common/geometry/footprint.h"
#include "tests/common/geometry/shapes.h"

namespace rlpos {
namespace {

using test_shapes::Courtyard;
using test_shapes::Rect;
using test_shapes::UShape;

bool InRectangle(const Bounds2& r, const Point2& p) {
  return p.x >= r.xmin && p.x <= r.xmax && p.y >= r.ymin && p.y <= r.ymax;
}

double TotalArea(const std::vector<Footprint>& pieces) {
  double sum = 0;
  for (const auto& piece : pieces)
    sum += Area(piece);
  return sum;
}

// Every piece valid; on an n x n grid of points over the rectangle (offset so that they miss the
// tests' round coordinates), a point is in a piece exactly when it is in the footprint and the
// rectangle; and the pieces' area is the sampled area of the intersection.
void ExpectExactClip(const Footprint& f, const Bounds2& r, int n = 200) {
  const std::vector<Footprint> pieces = ClipToRectangle(f, r);
  for (std::size_t k = 0; k < pieces.size(); ++k)
    EXPECT_EQ(FootprintDefect(pieces[k]), "") << "piece " << k;
  const double w = (r.xmax - r.xmin) / n, h = (r.ymax - r.ymin) / n;
  int hits = 0, mismatches = 0;
  for (int i = 0; i < n; ++i) {
    for (int j = 0; j < n; ++j) {
      const Point2 p{r.xmin + (i + 0.5137) * w, r.ymin + (j + 0.4771) * h};
      const bool want = Contains(f, p) && InRectangle(r, p);
      int in = 0;
      for (const auto& piece : pieces)
        in += Contains(piece, p) ? 1 : 0;
      hits += want ? 1 : 0;
      mismatches += (in == (want ? 1 : 0)) ? 0 : 1;
    }
  }
  EXPECT_EQ(mismatches, 0);
  const double sampled = hits * w * h;
  const double area = TotalArea(pieces);
  EXPECT_NEAR(area, sampled, 0.02 * (r.xmax - r.xmin) * (r.ymax - r.ymin) + 1e-9)
      << "pieces " << pieces.size();
}

TEST(ClipToRectangle, InsideUnchangedOutsideGone) {
  const Footprint square{Rect(2, 2, 8, 8), {}};
  const auto inside = ClipToRectangle(square, {0, 0, 10, 10});
  ASSERT_EQ(inside.size(), 1u);
  EXPECT_EQ(inside[0].outer.size(), 4u);
  EXPECT_DOUBLE_EQ(Area(inside[0]), 36.0);
  EXPECT_TRUE(ClipToRectangle(square, {20, 20, 30, 30}).empty());
  // Touching the rectangle's side from outside: no area inside.
  EXPECT_TRUE(ClipToRectangle(square, {8, 0, 20, 10}).empty());
  // Flush with the rectangle's side from inside: unchanged.
  EXPECT_EQ(ClipToRectangle(square, {2, 2, 20, 20}).size(), 1u);
}

TEST(ClipToRectangle, HalfASquare) {
  const auto pieces = ClipToRectangle({Rect(-5, 2, 5, 8), {}}, {0, 0, 10, 10});
  ASSERT_EQ(pieces.size(), 1u);
  EXPECT_DOUBLE_EQ(Area(pieces[0]), 30.0);
  EXPECT_EQ(BoundsOf(pieces[0].outer).xmin, 0.0);
}

TEST(ClipToRectangle, UShapeFallsIntoTwoPieces) {
  // The rectangle keeps y >= 5: the U's two arms, apart.
  const Bounds2 r{-1, 5, 11, 11};
  const auto pieces = ClipToRectangle({UShape(), {}}, r);
  ASSERT_EQ(pieces.size(), 2u);
  EXPECT_DOUBLE_EQ(Area(pieces[0]), 15.0);
  EXPECT_DOUBLE_EQ(Area(pieces[1]), 15.0);
  ExpectExactClip({UShape(), {}}, r);
  // A hole in each arm goes with its own arm.
  const Footprint holed{UShape(), {Rect(1, 6, 2, 8), Rect(8, 6, 9, 8)}};
  ASSERT_EQ(FootprintDefect(holed), "");
  const auto arms = ClipToRectangle(holed, r);
  ASSERT_EQ(arms.size(), 2u);
  EXPECT_EQ(arms[0].holes.size(), 1u);
  EXPECT_EQ(arms[1].holes.size(), 1u);
  ExpectExactClip(holed, r);
  // Cut exactly at the notch's floor (y = 3): vertices on the line.
  const auto at_floor = ClipToRectangle({UShape(), {}}, {-1, 3, 11, 11});
  EXPECT_EQ(at_floor.size(), 2u);
  EXPECT_DOUBLE_EQ(TotalArea(at_floor), 2 * 21.0);
  ExpectExactClip({UShape(), {}}, {-1, 3, 11, 11});
}

TEST(ClipToRectangle, Courtyards) {
  const Footprint c = Courtyard();  // [0, 20]^2 less [5, 15]^2
  // The courtyard inside: kept as a hole.
  auto pieces = ClipToRectangle(c, {-1, -1, 30, 30});
  ASSERT_EQ(pieces.size(), 1u);
  EXPECT_EQ(pieces[0].holes.size(), 1u);
  EXPECT_DOUBLE_EQ(Area(pieces[0]), 300.0);
  // Cut through the courtyard: the hole is cut too and touches the outer ring along x = 10.
  pieces = ClipToRectangle(c, {-1, -1, 10, 30});
  ASSERT_EQ(pieces.size(), 1u);
  ASSERT_EQ(pieces[0].holes.size(), 1u);
  EXPECT_DOUBLE_EQ(Area(pieces[0]), 200.0 - 50.0);
  EXPECT_FALSE(Contains(pieces[0], {7, 10}));
  EXPECT_TRUE(Contains(pieces[0], {2, 10}));
  ExpectExactClip(c, {-1, -1, 10, 30});
  // Wholly in the courtyard: nothing.
  EXPECT_TRUE(ClipToRectangle(c, {6, 6, 14, 14}).empty());
  // Off the courtyard: the hole is dropped.
  pieces = ClipToRectangle(c, {-1, -1, 4, 30});
  ASSERT_EQ(pieces.size(), 1u);
  EXPECT_TRUE(pieces[0].holes.empty());
  EXPECT_DOUBLE_EQ(Area(pieces[0]), 80.0);
}

// A comb with five teeth up, cut across the teeth: five pieces; cut along their tips' line and
// at their roots' line: vertices and edges on the cutting line.
TEST(ClipToRectangle, CombFallsIntoTeeth) {
  // Teeth [4k, 4k + 2] x [2, 6] on the base [0, 18] x [0, 2].
  Ring comb{{0, 0}, {18, 0}};
  for (int k = 4; k >= 0; --k) {
    comb.push_back({4.0 * k + 2, 6});
    comb.push_back({4.0 * k, 6});
    if (k > 0) {
      comb.push_back({4.0 * k, 2});
      comb.push_back({4.0 * k - 2, 2});
    }
  }
  const Footprint f{comb, {}};
  ASSERT_EQ(FootprintDefect(f), "");
  EXPECT_EQ(ClipToRectangle(f, {-1, 3, 20, 10}).size(), 5u);
  ExpectExactClip(f, {-1, 3, 20, 10});
  EXPECT_EQ(ClipToRectangle(f, {-1, 2, 20, 10}).size(), 5u);
  ExpectExactClip(f, {-1, 2, 20, 10});
  EXPECT_EQ(ClipToRectangle(f, {-1, -1, 20, 2}).size(), 1u);
  ExpectExactClip(f, {-1, -1, 20, 2});
  EXPECT_EQ(ClipToRectangle(f, {-1, 6, 20, 10}).size(), 0u);
}

// Random star polygons (some with a hole) against random rectangles: every piece valid, and
// exactly the intersection. Half of them on a whole-metre lattice, rectangles too, so that
// vertices and edges fall on the cutting lines.
TEST(ClipToRectangle, RandomShapesMatchSampling) {
  std::mt19937_64 rng(20261127);
  std::uniform_real_distribution<double> corner(-20, 20), size(5, 40);
  int several_pieces = 0, cut_holes = 0, on_lattice = 0;
  for (int trial = 0; trial < 200; ++trial) {
    const bool lattice = trial % 2 == 1;
    Footprint f{test_shapes::RandomStar(rng, 0, 0, 5, 20, 6 + trial % 20), {}};
    if (trial % 3 == 0)
      f.holes.push_back(test_shapes::RandomStar(rng, 0, 0, 1, 4, 5));
    Bounds2 r{corner(rng), corner(rng), 0, 0};
    r.xmax = r.xmin + size(rng);
    r.ymax = r.ymin + size(rng);
    if (lattice) {
      auto snap = [](Ring& ring) {
        for (auto& p : ring)
          p = {std::round(p.x), std::round(p.y)};
      };
      snap(f.outer);
      for (auto& hole : f.holes)
        snap(hole);
      r = {std::round(r.xmin), std::round(r.ymin), std::round(r.xmax), std::round(r.ymax)};
      if (!FootprintDefect(f).empty())
        continue;  // rounding made it cross itself
      ++on_lattice;
    }
    ASSERT_EQ(FootprintDefect(f), "") << "trial " << trial;
    SCOPED_TRACE("trial " + std::to_string(trial));
    ExpectExactClip(f, r, 120);
    const auto pieces = ClipToRectangle(f, r);
    several_pieces += pieces.size() > 1 ? 1 : 0;
    for (const auto& piece : pieces) {
      for (const auto& hole : piece.holes)
        cut_holes += hole.size() != f.holes[0].size() ? 1 : 0;
    }
  }
  // The draw reaches the cases that matter.
  EXPECT_GT(several_pieces, 5);
  EXPECT_GT(cut_holes, 2);
  EXPECT_GT(on_lattice, 50);
}

}  // namespace
}  // namespace rlpos
