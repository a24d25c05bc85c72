// The buildings of a view, shaded by height and outlined, far ones first: from above each one's
// ground shape (a footprint exactly, its courtyards open), from a side its silhouette.
#include <algorithm>
#include <cmath>

#include "worker/map/map_painter.h"

namespace rlpos::map {
namespace {

// How far from the viewer a building is along the view's depth axis: far ones are drawn first.
double DepthKey(const View& view, const BuildingSpec& b) {
  if (view.IsTop())
    return b.height;  // seen from above: the taller on top
  if (view.horizontal == Axis::kX)
    return -(b.ymin + b.ymax);  // from the south: the larger y, the farther
  return b.xmin + b.xmax;       // from the east: the smaller x, the farther
}

void BoxPath(cairo_t* cr, const View& view, const Vec3& lo, const Vec3& hi) {
  const double x0 = view.CanvasX(lo), x1 = view.CanvasX(hi);
  const double y0 = view.CanvasY(lo), y1 = view.CanvasY(hi);
  cairo_rectangle(cr, std::min(x0, x1), std::min(y0, y1), std::fabs(x1 - x0), std::fabs(y1 - y0));
}

// Each ring a closed sub-path of its own; filled even-odd, the holes stay open.
void FootprintPath(cairo_t* cr, const View& view, const Footprint& shape) {
  const auto ring_path = [&](const Ring& ring) {
    for (std::size_t k = 0; k < ring.size(); ++k) {
      const Vec3 p{ring[k].x, ring[k].y, 0.0};
      k == 0 ? cairo_move_to(cr, view.CanvasX(p), view.CanvasY(p))
             : cairo_line_to(cr, view.CanvasX(p), view.CanvasY(p));
    }
    cairo_close_path(cr);
  };
  ring_path(shape.outer);
  for (const Ring& hole : shape.holes)
    ring_path(hole);
}

}  // namespace

void PaintBuildings(cairo_t* cr, const Scenario& s, const View& view) {
  std::vector<std::size_t> order(s.buildings.size());
  for (std::size_t i = 0; i < order.size(); ++i)
    order[i] = i;
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    return DepthKey(view, s.buildings[a]) < DepthKey(view, s.buildings[b]);
  });
  for (std::size_t i : order) {
    const BuildingSpec& b = s.buildings[i];
    const bool exact = view.IsTop() && b.HasFootprint();
    if (exact) {
      FootprintPath(cr, view, b.footprint);
    } else {
      // A box from any side, a footprint from a side: the shape's extent along the view's axis
      // (its bounding box's) between min_height (a box's is 0) and height. A box keeps the
      // rectangle it always had, so that box-only maps keep their bytes.
      BoxPath(cr, view, {b.xmin, b.ymin, b.min_height}, {b.xmax, b.ymax, b.height});
    }
    SetColour(cr, BuildingColour(b.height, s.venue.height));
    // Even-odd for a footprint only: the rule shows in the SVG, and a box's must not change.
    cairo_set_fill_rule(cr, exact ? CAIRO_FILL_RULE_EVEN_ODD : CAIRO_FILL_RULE_WINDING);
    cairo_fill_preserve(cr);
    cairo_set_fill_rule(cr, CAIRO_FILL_RULE_WINDING);
    SetColour(cr, kInk);
    cairo_set_line_width(cr, 0.8);
    cairo_stroke(cr);
  }
}

}  // namespace rlpos::map
