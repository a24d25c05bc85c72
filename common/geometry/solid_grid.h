#pragma once
// A uniform grid over the ground bounds of a list of solids, so that a query looks only at the
// solids near it: each cell lists, in index order, the solids whose bounds (padded a little)
// overlap it. Conservative: a solid a point or segment may touch, to rounding, is never left out.
#include <cstddef>
#include <vector>

#include "common/geometry/footprint.h"

namespace rlpos {

class SolidGrid {
 public:
  SolidGrid() = default;
  explicit SolidGrid(const std::vector<Bounds2>& bounds);

  // The solids listed in the cell of (x, y), in index order: [begin, end). None off the grid.
  std::pair<const int*, const int*> At(double x, double y) const;
  // The solids listed in the cells the segment [a, b] may cross, each once, in index order,
  // into `out` (cleared first).
  void Along(const Point2& a, const Point2& b, std::vector<int>& out) const;

  std::size_t columns() const { return nx_; }
  std::size_t rows() const { return ny_; }

 private:
  std::size_t Column(double x) const;
  std::size_t Row(double y) const;
  void AppendCell(std::size_t row, std::size_t column, std::vector<int>& out) const;

  double x0_ = 0, y0_ = 0, x1_ = 0, y1_ = 0;  // the grid's extent
  double cell_w_ = 1, cell_h_ = 1;
  double pad_ = 0;  // how far past a solid's bounds its cells reach (m)
  std::size_t nx_ = 0, ny_ = 0;
  // Cell c (row-major) lists items_[starts_[c] .. starts_[c + 1]).
  std::vector<std::size_t> starts_;
  std::vector<int> items_;
};

}  // namespace rlpos
