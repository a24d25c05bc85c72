#include "worker/map/map_layout.h"

#include <algorithm>

namespace rlpos::map {
namespace {

constexpr double kViewSide = 540;    // points of the venue's longer side
constexpr double kTitleHeight = 52;  // title and subtitle above the views
constexpr double kLeftMargin = 58;   // room for the y axis' labels
constexpr double kAxisMargin = 46;   // below a view: the x axis' labels and title
constexpr double kViewGap = 74;      // between views side by side (the next one's y labels)
constexpr double kLegendGap = 28;
constexpr double kLegendWidth = 250;
constexpr double kOuterMargin = 16;

}  // namespace

double Coordinate(const Vec3& p, Axis axis) {
  return axis == Axis::kX ? p.x : axis == Axis::kY ? p.y : p.z;
}

MapLayout ComputeLayout(const MapScene& scene, double legend_height) {
  const Venue& v = scene.scenario.venue;
  MapLayout layout;
  layout.scale = kViewSide / std::max(v.width, v.depth);
  layout.side = scene.side_views;
  layout.title_top = kOuterMargin;
  const double s = layout.scale;
  // With side views each view has a title of its own above it.
  const double title_height = kTitleHeight + (layout.side ? 16 : 0);
  layout.top = {{kLeftMargin, title_height + kOuterMargin, v.width * s, v.depth * s},
                Axis::kX,
                Axis::kY,
                s,
                "top view"};
  double views_right = layout.top.rect.right();
  double views_bottom = layout.top.rect.bottom() + kAxisMargin;
  if (layout.side) {
    // x-z under the top view (x aligned with it), y-z beside x-z; the legend above y-z.
    const double row = layout.top.rect.bottom() + kAxisMargin + 22;
    layout.xz = {{kLeftMargin, row, v.width * s, v.height * s},
                 Axis::kX,
                 Axis::kZ,
                 s,
                 "elevation from the south (x-z)"};
    layout.yz = {{layout.xz.rect.right() + kViewGap, row, v.depth * s, v.height * s},
                 Axis::kY,
                 Axis::kZ,
                 s,
                 "elevation from the east (y-z)"};
    views_right = std::max(views_right, layout.yz.rect.right());
    views_bottom = layout.xz.rect.bottom() + kAxisMargin;
  }
  double legend_left = layout.top.rect.right() + kLegendGap;
  if (layout.side) {
    legend_left = std::max(layout.yz.rect.left, legend_left);
    // A legend taller than the top view's row goes right of the y-z view instead.
    if (layout.top.rect.top + legend_height > layout.xz.rect.top - 30)
      legend_left = layout.yz.rect.right() + kLegendGap;
  }
  layout.legend = {legend_left, layout.top.rect.top, kLegendWidth, legend_height};
  layout.width = std::max(views_right, layout.legend.right()) + kOuterMargin;
  layout.height = std::max(views_bottom, layout.legend.bottom() + kOuterMargin);
  return layout;
}

}  // namespace rlpos::map
