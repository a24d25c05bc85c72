#include "common/geometry/solid_grid.h"

#include <algorithm>
#include <cmath>

namespace rlpos {
namespace {

// Rounding in the solids' own tests moves a boundary by a few ulps of the coordinates; the pad
// is many orders of magnitude wider, and still well under a millimetre in any city.
double PadFor(double magnitude) {
  return 1e-9 * (1.0 + magnitude);
}

// About two cells per solid: each solid then sits in a few cells and a cell holds a few solids.
constexpr double kCellsPerSolid = 2.0;
constexpr double kMaxCells = 4.0 * 1024 * 1024;

}  // namespace

SolidGrid::SolidGrid(const std::vector<Bounds2>& bounds) {
  if (bounds.empty())
    return;
  solids_ = bounds.size();
  Bounds2 all = bounds[0];
  for (const auto& b : bounds) {
    all.xmin = std::min(all.xmin, b.xmin);
    all.ymin = std::min(all.ymin, b.ymin);
    all.xmax = std::max(all.xmax, b.xmax);
    all.ymax = std::max(all.ymax, b.ymax);
  }
  pad_ = PadFor(std::max({std::abs(all.xmin), std::abs(all.xmax), std::abs(all.ymin),
                          std::abs(all.ymax), all.xmax - all.xmin, all.ymax - all.ymin}));
  x0_ = all.xmin - pad_;
  y0_ = all.ymin - pad_;
  x1_ = all.xmax + pad_;
  y1_ = all.ymax + pad_;
  const double w = x1_ - x0_, h = y1_ - y0_;
  const double cells = std::min(kMaxCells, std::max(1.0, kCellsPerSolid * bounds.size()));
  const double side = std::sqrt(w * h / cells);
  nx_ = static_cast<std::size_t>(std::clamp(std::ceil(w / side), 1.0, cells));
  ny_ = static_cast<std::size_t>(std::clamp(std::ceil(h / side), 1.0, cells));
  cell_w_ = w / static_cast<double>(nx_);
  cell_h_ = h / static_cast<double>(ny_);
  // Counting pass, then filling: one flat array for all cells.
  std::vector<std::size_t> counts(nx_ * ny_ + 1, 0);
  auto for_cells = [&](const Bounds2& b, auto&& visit) {
    const std::size_t c0 = Column(b.xmin - pad_), c1 = Column(b.xmax + pad_);
    const std::size_t r0 = Row(b.ymin - pad_), r1 = Row(b.ymax + pad_);
    for (std::size_t r = r0; r <= r1; ++r) {
      for (std::size_t c = c0; c <= c1; ++c)
        visit(r * nx_ + c);
    }
  };
  for (const auto& b : bounds)
    for_cells(b, [&](std::size_t cell) { ++counts[cell + 1]; });
  for (std::size_t c = 1; c < counts.size(); ++c)
    counts[c] += counts[c - 1];
  starts_ = counts;
  items_.resize(starts_.back());
  for (std::size_t i = 0; i < bounds.size(); ++i)
    for_cells(bounds[i], [&](std::size_t cell) { items_[counts[cell]++] = static_cast<int>(i); });
}

namespace {

// The index of cell `c` (a floor) in [0, n - 1]; a NaN falls in cell 0 rather than being cast.
std::size_t Clamped(double c, std::size_t n) {
  if (!(c > 0))
    return 0;
  return c >= static_cast<double>(n - 1) ? n - 1 : static_cast<std::size_t>(c);
}

}  // namespace

std::size_t SolidGrid::Column(double x) const {
  return Clamped(std::floor((x - x0_) / cell_w_), nx_);
}

std::size_t SolidGrid::Row(double y) const {
  return Clamped(std::floor((y - y0_) / cell_h_), ny_);
}

std::pair<const int*, const int*> SolidGrid::At(double x, double y) const {
  if (nx_ == 0 || !(x >= x0_ && x <= x1_ && y >= y0_ && y <= y1_))
    return {nullptr, nullptr};
  const std::size_t cell = Row(y) * nx_ + Column(x);
  return {items_.data() + starts_[cell], items_.data() + starts_[cell + 1]};
}

SolidGrid::Met& SolidGrid::Met::ForThisThread() {
  thread_local Met met;
  return met;
}

void SolidGrid::Met::Begin(std::size_t solids) {
  if (stamps_.size() < solids)
    stamps_.resize(solids, 0);
  if (++now_ == 0) {  // wrapped round: old stamps could pass for new ones
    std::fill(stamps_.begin(), stamps_.end(), 0);
    now_ = 1;
  }
}

bool SolidGrid::FirstRow(const Point2& a, const Point2& b, Rows& rows) const {
  if (nx_ == 0)
    return false;
  rows.pad = std::max(
      pad_, PadFor(std::max({std::abs(a.x), std::abs(a.y), std::abs(b.x), std::abs(b.y)})));
  const double ylo = std::min(a.y, b.y) - rows.pad, yhi = std::max(a.y, b.y) + rows.pad;
  if (!(yhi >= y0_ && ylo <= y1_ && std::max(a.x, b.x) + rows.pad >= x0_ &&
        std::min(a.x, b.x) - rows.pad <= x1_))
    return false;
  rows.up = a.y <= b.y;
  rows.row = rows.up ? Row(ylo) : Row(yhi);
  rows.last = rows.up ? Row(yhi) : Row(ylo);
  return true;
}

// The x range the segment spans within the row's y range (both widened by the pad), and the
// cells of that range, which lie next to each other in items_.
bool SolidGrid::RowItems(const Point2& a, const Point2& b, double pad, std::size_t r,
                         const int*& begin, const int*& end) const {
  double xlo = std::min(a.x, b.x), xhi = std::max(a.x, b.x);
  if (a.y != b.y) {
    const double row_lo = y0_ + static_cast<double>(r) * cell_h_ - pad;
    const double row_hi = y0_ + static_cast<double>(r + 1) * cell_h_ + pad;
    const double t0 = std::clamp((row_lo - a.y) / (b.y - a.y), 0.0, 1.0);
    const double t1 = std::clamp((row_hi - a.y) / (b.y - a.y), 0.0, 1.0);
    const double x_t0 = a.x + t0 * (b.x - a.x), x_t1 = a.x + t1 * (b.x - a.x);
    xlo = std::min(x_t0, x_t1);
    xhi = std::max(x_t0, x_t1);
  }
  if (xhi + pad < x0_ || xlo - pad > x1_)
    return false;
  const std::size_t c0 = Column(xlo - pad), c1 = Column(xhi + pad);
  begin = items_.data() + starts_[r * nx_ + c0];
  end = items_.data() + starts_[r * nx_ + c1 + 1];
  return true;
}

void SolidGrid::Along(const Point2& a, const Point2& b, std::vector<int>& out) const {
  out.clear();
  AnyAlong(a, b, [&](int i) {
    out.push_back(i);
    return false;
  });
}

}  // namespace rlpos
