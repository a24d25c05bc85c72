#pragma once
// Where each part of a map goes on the canvas (in points; a PNG has kPngPixelsPerPoint pixels per
// point): the top view, the elevation views (--side), the legend. One scale, metres to points,
// for every view, so that heights and distances compare at a glance.
#include "common/scenario/scenario.h"
#include "worker/map/map_scene.h"

namespace rlpos::map {

constexpr double kPngPixelsPerPoint = 2.0;

struct Rect {
  double left = 0, top = 0, width = 0, height = 0;
  double right() const { return left + width; }
  double bottom() const { return top + height; }
};

enum class Axis { kX, kY, kZ };
double Coordinate(const Vec3& p, Axis axis);

// One view of the venue: its horizontal and vertical axes, and where it sits on the canvas.
struct View {
  Rect rect;
  Axis horizontal = Axis::kX, vertical = Axis::kY;
  double scale = 1;  // points per metre
  const char* title = "";
  // The canvas point of a venue point.
  double CanvasX(const Vec3& p) const { return rect.left + Coordinate(p, horizontal) * scale; }
  double CanvasY(const Vec3& p) const { return rect.bottom() - Coordinate(p, vertical) * scale; }
  bool IsTop() const { return vertical == Axis::kY; }
};

struct MapLayout {
  double width = 0, height = 0;  // the canvas
  double scale = 1;              // points per metre
  double title_top = 0;
  View top;
  bool side = false;
  View xz, yz;  // when side
  Rect legend;
};

// The layout of `scene`; `legend_height` is what its legend needs (LegendHeight, map_painter.h).
MapLayout ComputeLayout(const MapScene& scene, double legend_height);

}  // namespace rlpos::map
