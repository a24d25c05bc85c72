#include "common/scenario_import/footprint_overlaps.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <sstream>
#include <unordered_map>

#include "common/scenario/building_checks.h"

namespace rlpos {
namespace {

// Cells of the vertex grid (m); larger than the snapping distance.
constexpr double kCell = 1.0;

bool SamePoint(const Point2& a, const Point2& b) {
  return a.x == b.x && a.y == b.y;
}

double Distance(const Point2& a, const Point2& b) {
  return std::hypot(a.x - b.x, a.y - b.y);
}

// The parameter of p's projection on a -> b, and its distance from the segment.
double Along(const Point2& p, const Point2& a, const Point2& b) {
  const double dx = b.x - a.x, dy = b.y - a.y;
  const double len2 = dx * dx + dy * dy;
  return len2 == 0 ? 0 : ((p.x - a.x) * dx + (p.y - a.y) * dy) / len2;
}
double SegmentDistance(const Point2& p, const Point2& a, const Point2& b) {
  const double t = std::clamp(Along(p, a, b), 0.0, 1.0);
  return Distance(p, {a.x + t * (b.x - a.x), a.y + t * (b.y - a.y)});
}

template <typename F>
void ForEachRing(const Footprint& f, F&& fn) {
  fn(f.outer);
  for (const auto& hole : f.holes)
    fn(hole);
}

bool BoxesMeet(const Bounds2& a, const Bounds2& b, double slack) {
  return a.xmin <= b.xmax + slack && b.xmin <= a.xmax + slack && a.ymin <= b.ymax + slack &&
         b.ymin <= a.ymax + slack;
}

long long CellKey(long long cx, long long cy) {
  return cx * 1000003LL + cy;
}
long long CellOf(double v) {
  return static_cast<long long>(std::floor(v / kCell));
}

// The corners of all buildings by grid cell: (building, point).
class CornerGrid {
 public:
  void Add(std::size_t owner, const Point2& p) {
    cells_[CellKey(CellOf(p.x), CellOf(p.y))].push_back({owner, p});
  }
  template <typename F>
  void ForEachNear(const Bounds2& box, double slack, F&& fn) const {
    for (long long cx = CellOf(box.xmin - slack); cx <= CellOf(box.xmax + slack); ++cx) {
      for (long long cy = CellOf(box.ymin - slack); cy <= CellOf(box.ymax + slack); ++cy) {
        const auto cell = cells_.find(CellKey(cx, cy));
        if (cell == cells_.end())
          continue;
        for (const auto& [owner, p] : cell->second)
          fn(owner, p);
      }
    }
  }

 private:
  std::unordered_map<long long, std::vector<std::pair<std::size_t, Point2>>> cells_;
};

void DropRepeatedCorners(Ring& ring) {
  Ring out;
  for (const auto& p : ring) {
    if (out.empty() || !SamePoint(out.back(), p))
      out.push_back(p);
  }
  while (out.size() > 1 && SamePoint(out.front(), out.back()))
    out.pop_back();
  ring = std::move(out);
}

// Corners of smaller buildings move onto the nearest corner of a larger one within the snapping
// distance.
void SnapCorners(std::vector<PlaceBuilding>& b, const std::vector<std::size_t>& order) {
  CornerGrid anchors;
  for (std::size_t i : order) {
    auto snap_ring = [&](Ring& ring) {
      for (auto& p : ring) {
        double best = kSnapDistance;
        std::optional<Point2> to;
        anchors.ForEachNear({p.x, p.y, p.x, p.y}, kSnapDistance, [&](std::size_t, const Point2& q) {
          const double d = Distance(p, q);
          if (d > 0 && d <= best) {
            best = d;
            to = q;
          }
        });
        if (to)
          p = *to;
      }
      DropRepeatedCorners(ring);
    };
    snap_ring(b[i].footprint.outer);
    for (auto& hole : b[i].footprint.holes)
      snap_ring(hole);
    ForEachRing(b[i].footprint, [&](const Ring& ring) {
      for (const auto& p : ring)
        anchors.Add(i, p);
    });
  }
}

// Corners of other buildings within the snapping distance of a wall become corners of it.
void SnapWalls(std::vector<PlaceBuilding>& b) {
  CornerGrid corners;
  for (std::size_t i = 0; i < b.size(); ++i) {
    ForEachRing(b[i].footprint, [&](const Ring& ring) {
      for (const auto& p : ring)
        corners.Add(i, p);
    });
  }
  for (std::size_t i = 0; i < b.size(); ++i) {
    auto node_ring = [&](Ring& ring) {
      Ring out;
      for (std::size_t k = 0; k < ring.size(); ++k) {
        const Point2 a = ring[k], c = ring[(k + 1) % ring.size()];
        out.push_back(a);
        std::vector<std::pair<double, Point2>> inserted;
        const Bounds2 box{std::min(a.x, c.x), std::min(a.y, c.y), std::max(a.x, c.x),
                          std::max(a.y, c.y)};
        corners.ForEachNear(box, kSnapDistance, [&](std::size_t owner, const Point2& p) {
          if (owner == i || SamePoint(p, a) || SamePoint(p, c))
            return;
          const double t = Along(p, a, c);
          if (t > 0 && t < 1 && SegmentDistance(p, a, c) <= kSnapDistance)
            inserted.push_back({t, p});
        });
        std::sort(inserted.begin(), inserted.end(), [](const auto& x, const auto& y) {
          return x.first < y.first ||
                 (x.first == y.first && (x.second.x < y.second.x ||
                                         (x.second.x == y.second.x && x.second.y < y.second.y)));
        });
        for (const auto& [t, p] : inserted) {
          if (!SamePoint(out.back(), p))
            out.push_back(p);
        }
      }
      ring = std::move(out);
      DropRepeatedCorners(ring);
    };
    node_ring(b[i].footprint.outer);
    for (auto& hole : b[i].footprint.holes)
      node_ring(hole);
  }
}

// Every corner of `inner` lies in `outer` (its walls included).
bool WithinFootprint(const Footprint& inner, const Footprint& outer) {
  return std::all_of(inner.outer.begin(), inner.outer.end(),
                     [&](const Point2& p) { return Contains(outer, p); });
}

std::string MetresText(double v) {
  std::ostringstream out;
  out << v << " m";
  return out.str();
}

std::vector<Bounds2> WallBoxes(const std::vector<PlaceBuilding>& b) {
  std::vector<Bounds2> boxes;
  for (const auto& x : b)
    boxes.push_back(BoundsOf(x.footprint.outer));
  return boxes;
}

std::vector<std::size_t> LargestFirst(const std::vector<PlaceBuilding>& buildings) {
  std::vector<std::size_t> order(buildings.size());
  std::iota(order.begin(), order.end(), 0);
  std::vector<double> area;
  for (const auto& b : buildings)
    area.push_back(Area(b.footprint));
  std::stable_sort(order.begin(), order.end(),
                   [&](std::size_t x, std::size_t y) { return area[x] > area[y]; });
  return order;
}

// The scenario's own rule, with boxes first to keep it quick.
class OverlapTest {
 public:
  explicit OverlapTest(const std::vector<PlaceBuilding>& buildings) { Update(buildings); }

  void Update(const std::vector<PlaceBuilding>& buildings) {
    specs_.clear();
    for (const auto& b : buildings)
      specs_.push_back(PlaceBuildingSpec(b));
    boxes_ = WallBoxes(buildings);
  }
  // After a change of heights only: the walls' boxes stay.
  void UpdateHeights(const PlaceBuilding& building, std::size_t i) {
    specs_[i] = PlaceBuildingSpec(building);
  }
  bool operator()(std::size_t i, std::size_t j) const {
    return BoxesMeet(boxes_[i], boxes_[j], 0) && BuildingsOverlap(specs_[i], specs_[j]);
  }

 private:
  std::vector<BuildingSpec> specs_;
  std::vector<Bounds2> boxes_;
};

// Pairs (i < j) that overlap.
std::vector<std::pair<std::size_t, std::size_t>> OverlappingPairs(std::size_t n,
                                                                  const OverlapTest& overlapping) {
  std::vector<std::pair<std::size_t, std::size_t>> pairs;
  for (std::size_t i = 0; i < n; ++i) {
    for (std::size_t j = i + 1; j < n; ++j) {
      if (overlapping(i, j))
        pairs.push_back({i, j});
    }
  }
  return pairs;
}

// Snaps corners and walls; a snap that left a ring that is not simple is undone: that building
// keeps its walls.
void SnapKeepingSimpleRings(std::vector<PlaceBuilding>& buildings,
                            const std::vector<std::size_t>& order) {
  const std::vector<PlaceBuilding> original = buildings;
  SnapCorners(buildings, order);
  SnapWalls(buildings);
  for (std::size_t i = 0; i < buildings.size(); ++i) {
    if (!FootprintDefect(buildings[i].footprint).empty())
      buildings[i].footprint = original[i].footprint;
  }
}

// Goes through the buildings larger first: a building is kept unless it overlaps one kept
// already.
class KeepLargerFirst {
 public:
  KeepLargerFirst(std::vector<PlaceBuilding>& buildings, double level_height,
                  OverlapTest& overlapping, OverlapCounts& counts,
                  std::vector<ImportWarning>& warnings)
      : buildings_(buildings),
        level_height_(level_height),
        overlapping_(overlapping),
        counts_(counts),
        warnings_(warnings),
        dropped_(buildings.size(), false) {}

  // Which buildings are dropped.
  std::vector<bool> Run(const std::vector<std::size_t>& order) {
    for (std::size_t i : order) {
      for (bool again = true; again && !dropped_[i];) {
        again = false;
        for (std::size_t j : kept_) {
          if (!overlapping_(i, j))
            continue;
          again = SettleOverlap(i, j);
          break;
        }
      }
      if (!dropped_[i])
        kept_.push_back(i);
    }
    return dropped_;
  }

 private:
  // Stacks building i on the kept building j it overlaps (true: it may overlap others now) or
  // drops it.
  bool SettleOverlap(std::size_t i, std::size_t j) {
    const ResolvedHeight& a = buildings_[i].height;
    const ResolvedHeight& b = buildings_[j].height;
    if (WithinFootprint(buildings_[i].footprint, buildings_[j].footprint)) {
      if (a.height > b.height && b.min_height <= a.min_height) {
        StackOnTop(i, j);
        return true;
      }
      if (a.height <= b.height && a.min_height >= b.min_height) {
        Drop(i, j, "lies within the volume of the larger building");
        return false;
      }
    }
    Drop(i, j, "overlaps the larger building");
    return false;
  }

  // A taller part drawn inside a larger one from the ground (a dome on its church): the part
  // above the larger one's top is what it adds.
  void StackOnTop(std::size_t i, std::size_t j) {
    ResolvedHeight& a = buildings_[i].height;
    const ResolvedHeight& b = buildings_[j].height;
    warnings_.push_back({buildings_[i].source,
                         "stands inside \"" + buildings_[j].name + "\" (" + buildings_[j].source +
                             "): it starts on its top, " + MetresText(b.height)});
    a.min_height = b.height;
    a.floors = std::max(1, static_cast<int>(std::floor((a.height - a.min_height) / level_height_)));
    overlapping_.UpdateHeights(buildings_[i], i);
    ++counts_.stacked;
  }

  void Drop(std::size_t i, std::size_t j, const std::string& why) {
    dropped_[i] = true;
    ++counts_.dropped;
    warnings_.push_back({buildings_[i].source, why + " \"" + buildings_[j].name + "\" (" +
                                                   buildings_[j].source + "): dropped"});
  }

  std::vector<PlaceBuilding>& buildings_;
  double level_height_;
  OverlapTest& overlapping_;
  OverlapCounts& counts_;
  std::vector<ImportWarning>& warnings_;
  std::vector<bool> dropped_;
  std::vector<std::size_t> kept_;
};

}  // namespace

void ResolveOverlaps(std::vector<PlaceBuilding>& buildings, double level_height,
                     OverlapCounts& counts, std::vector<ImportWarning>& warnings) {
  const std::vector<std::size_t> order = LargestFirst(buildings);
  OverlapTest overlapping(buildings);
  // Pairs that overlap as the map drew them.
  const auto overlapping_before = OverlappingPairs(buildings.size(), overlapping);
  SnapKeepingSimpleRings(buildings, order);
  overlapping.Update(buildings);
  for (const auto& [i, j] : overlapping_before) {
    if (!overlapping(i, j))
      ++counts.trimmed;
  }
  const std::vector<bool> dropped =
      KeepLargerFirst(buildings, level_height, overlapping, counts, warnings).Run(order);
  std::vector<PlaceBuilding> out;
  for (std::size_t i = 0; i < buildings.size(); ++i) {
    if (!dropped[i])
      out.push_back(std::move(buildings[i]));
  }
  buildings = std::move(out);
}

}  // namespace rlpos
