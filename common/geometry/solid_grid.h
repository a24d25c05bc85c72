#pragma once
// A uniform grid over the ground bounds of a list of solids, so that a query looks only at the
// solids near it: each cell lists, in index order, the solids whose bounds (padded a little)
// overlap it. Conservative: a solid a point or segment may touch, to rounding, is never left out.
#include <cstddef>
#include <cstdint>
#include <vector>

#include "common/geometry/footprint.h"

namespace rlpos {

class SolidGrid {
 public:
  SolidGrid() = default;
  explicit SolidGrid(const std::vector<Bounds2>& bounds);

  // The solids listed in the cell of (x, y), in index order: [begin, end). None off the grid.
  std::pair<const int*, const int*> At(double x, double y) const;
  // Calls visit(i) for the solids listed in the cells the segment [a, b] may cross, each once,
  // until a call returns true; says whether one did. The cells go row by row from a's end, then
  // column by column. No sort and no allocation: a per-thread stamp per solid tells which ones
  // this query has met already (so `visit` must not query a grid itself).
  template <typename Visit>
  bool AnyAlong(const Point2& a, const Point2& b, Visit&& visit) const;
  // The same solids into `out` (cleared first), in that order.
  void Along(const Point2& a, const Point2& b, std::vector<int>& out) const;

  std::size_t columns() const { return nx_; }
  std::size_t rows() const { return ny_; }

 private:
  // The solids a query has met: a stamp per solid, and a new stamp per query, so that nothing
  // is cleared per query. One per thread (ForThisThread).
  class Met {
   public:
    static Met& ForThisThread();
    void Begin(std::size_t solids);
    bool First(int i) {
      std::uint32_t& stamp = stamps_[static_cast<std::size_t>(i)];
      if (stamp == now_)
        return false;
      stamp = now_;
      return true;
    }

   private:
    std::vector<std::uint32_t> stamps_;
    std::uint32_t now_ = 0;
  };
  // A segment's rows of cells, from a's end.
  struct Rows {
    double pad = 0;
    std::size_t row = 0, last = 0;
    bool up = true;
  };
  // False when the segment misses the grid.
  bool FirstRow(const Point2& a, const Point2& b, Rows& rows) const;
  // The solids of the cells of row `r` the segment may cross, as one range (a solid may come
  // more than once); false when it crosses none there.
  bool RowItems(const Point2& a, const Point2& b, double pad, std::size_t r, const int*& begin,
                const int*& end) const;
  std::size_t Column(double x) const;
  std::size_t Row(double y) const;

  double x0_ = 0, y0_ = 0, x1_ = 0, y1_ = 0;  // the grid's extent
  double cell_w_ = 1, cell_h_ = 1;
  double pad_ = 0;  // how far past a solid's bounds its cells reach (m)
  std::size_t nx_ = 0, ny_ = 0;
  std::size_t solids_ = 0;
  // Cell c (row-major) lists items_[starts_[c] .. starts_[c + 1]).
  std::vector<std::size_t> starts_;
  std::vector<int> items_;
};

template <typename Visit>
bool SolidGrid::AnyAlong(const Point2& a, const Point2& b, Visit&& visit) const {
  Rows rows;
  if (!FirstRow(a, b, rows))
    return false;
  Met& met = Met::ForThisThread();
  met.Begin(solids_);
  for (std::size_t r = rows.row;; r = rows.up ? r + 1 : r - 1) {
    const int* begin = nullptr;
    const int* end = nullptr;
    if (RowItems(a, b, rows.pad, r, begin, end)) {
      for (const int* i = begin; i != end; ++i) {
        if (met.First(*i) && visit(*i))
          return true;
      }
    }
    if (r == rows.last)
      return false;
  }
}

}  // namespace rlpos
