#include <algorithm>
#include <cmath>

#include "worker/map/map_painter.h"

namespace rlpos::map {
namespace {

constexpr double kPi = 3.14159265358979323846;

void PaintZones(cairo_t* cr, const Scenario& s, const View& view) {
  const double dashes[] = {6.0, 4.0};
  cairo_save(cr);
  cairo_set_dash(cr, dashes, 2, 0);
  cairo_set_line_width(cr, 1.4);
  SetColour(cr, kZone);
  for (std::size_t u = 0; u < s.uavs.size(); ++u) {
    const Box& z = s.uavs[u].zone;
    bool seen = false;  // UAVs sharing a zone draw it once
    for (std::size_t v = 0; v < u; ++v) {
      const Box& o = s.uavs[v].zone;
      seen = seen || (o.xmin == z.xmin && o.xmax == z.xmax && o.ymin == z.ymin &&
                      o.ymax == z.ymax && o.zmin == z.zmin && o.zmax == z.zmax);
    }
    if (seen)
      continue;
    // Drawn 2 pt inside its true edges: a zone along the venue's edge would otherwise hide
    // under the frame.
    const double x0 = view.CanvasX({z.xmin, z.ymin, z.zmin}),
                 x1 = view.CanvasX({z.xmax, z.ymax, z.zmax});
    const double y0 = view.CanvasY({z.xmin, z.ymin, z.zmin}),
                 y1 = view.CanvasY({z.xmax, z.ymax, z.zmax});
    cairo_rectangle(cr, std::min(x0, x1) + 2, std::min(y0, y1) + 2, std::fabs(x1 - x0) - 4,
                    std::fabs(y1 - y0) - 4);
    cairo_stroke(cr);
  }
  cairo_restore(cr);
}

void PaintLinks(cairo_t* cr, const MapScene& scene, const View& view) {
  if (scene.links.empty() || scene.placements.size() != 1)
    return;
  const Placement& uavs = scene.placements.front().positions;
  const double dashes[] = {5.0, 3.5};
  cairo_save(cr);
  cairo_set_line_width(cr, 1.3);
  for (std::size_t i = 0; i < scene.links.size(); ++i) {
    const MapLink& link = scene.links[i];
    const Vec3& ue = scene.scenario.ues[i].position;
    const Vec3& uav = uavs.at(static_cast<std::size_t>(link.serving_uav));
    cairo_set_dash(cr, dashes, link.los ? 0 : 2, 0);
    SetColour(cr, UeColour(scene, i), 0.9);
    cairo_move_to(cr, view.CanvasX(ue), view.CanvasY(ue));
    cairo_line_to(cr, view.CanvasX(uav), view.CanvasY(uav));
    cairo_stroke(cr);
  }
  cairo_restore(cr);
}

void PaintArrowHead(cairo_t* cr, double x0, double y0, double x1, double y1) {
  const double a = std::atan2(y1 - y0, x1 - x0), len = 9, spread = 0.45;
  cairo_move_to(cr, x1, y1);
  cairo_line_to(cr, x1 - len * std::cos(a - spread), y1 - len * std::sin(a - spread));
  cairo_line_to(cr, x1 - len * std::cos(a + spread), y1 - len * std::sin(a + spread));
  cairo_close_path(cr);
  cairo_fill(cr);
}

void PaintFlight(cairo_t* cr, const MapScene& scene, const View& view) {
  for (const FlightPath& path : scene.flight) {
    if (path.points.size() < 2)
      continue;
    SetColour(cr, kFlight);
    cairo_set_line_width(cr, 1.6);
    cairo_set_line_join(cr, CAIRO_LINE_JOIN_ROUND);
    for (std::size_t k = 0; k < path.points.size(); ++k) {
      const Vec3& p = path.points[k];
      k == 0 ? cairo_move_to(cr, view.CanvasX(p), view.CanvasY(p))
             : cairo_line_to(cr, view.CanvasX(p), view.CanvasY(p));
    }
    cairo_stroke(cr);
    for (const Vec3& p : path.points) {
      cairo_new_sub_path(cr);
      cairo_arc(cr, view.CanvasX(p), view.CanvasY(p), 1.8, 0, 2 * kPi);
    }
    cairo_fill(cr);
    // The arrow points along the last move that went somewhere.
    std::size_t last = path.points.size() - 1, before = last;
    while (before > 0 && view.CanvasX(path.points[before]) == view.CanvasX(path.points[last]) &&
           view.CanvasY(path.points[before]) == view.CanvasY(path.points[last]))
      --before;
    if (before != last) {
      const Vec3 &a = path.points[before], &b = path.points[last];
      PaintArrowHead(cr, view.CanvasX(a), view.CanvasY(a), view.CanvasX(b), view.CanvasY(b));
    }
  }
}

// Thin lines under the UEs, an arrow at each path's end: where each moving UE walks.
void PaintUePaths(cairo_t* cr, const MapScene& scene, const View& view) {
  cairo_save(cr);
  SetColour(cr, kUePath, 0.85);
  cairo_set_line_width(cr, 1.0);
  cairo_set_line_join(cr, CAIRO_LINE_JOIN_ROUND);
  for (const auto& path : scene.ue_paths) {
    if (path.size() < 2)
      continue;
    for (std::size_t k = 0; k < path.size(); ++k) {
      const Vec3& p = path[k];
      k == 0 ? cairo_move_to(cr, view.CanvasX(p), view.CanvasY(p))
             : cairo_line_to(cr, view.CanvasX(p), view.CanvasY(p));
    }
    cairo_stroke(cr);
    const Vec3 &a = path[path.size() - 2], &b = path.back();
    PaintArrowHead(cr, view.CanvasX(a), view.CanvasY(a), view.CanvasX(b), view.CanvasY(b));
  }
  cairo_restore(cr);
}

void PaintUes(cairo_t* cr, const MapScene& scene, const View& view) {
  for (std::size_t i = 0; i < scene.scenario.ues.size(); ++i) {
    const Vec3& p = scene.scenario.ues[i].position;
    PaintMarker(cr, MarkerShape::kCircle, view.CanvasX(p), view.CanvasY(p), kUeMarkerSize,
                UeColour(scene, i), true);
  }
}

void PaintUavs(cairo_t* cr, const MapScene& scene, const View& view) {
  const bool several_uavs = scene.scenario.uavs.size() > 1;
  if (scene.placements.size() == 1) {
    const Placement& positions = scene.placements.front().positions;
    for (std::size_t u = 0; u < positions.size(); ++u) {
      const Rgb colour = several_uavs ? UavColour(static_cast<int>(u)) : kInk;
      PaintUavGlyph(cr, view.CanvasX(positions[u]), view.CanvasY(positions[u]), kUavGlyphSize,
                    colour);
    }
    return;
  }
  // Markers on one spot of the view grow by turns and are drawn largest first: concentric
  // outlines, every one visible.
  struct Mark {
    double x, y, size;
    PlacementStyle style;
  };
  std::vector<Mark> marks;
  for (std::size_t k = 0; k < scene.placements.size(); ++k) {
    for (const Vec3& p : scene.placements[k].positions) {
      Mark m{view.CanvasX(p), view.CanvasY(p), kPlacementMarkerSize,
             PlacementStyleOf(static_cast<int>(k))};
      for (const Mark& o : marks) {
        if (std::hypot(o.x - m.x, o.y - m.y) < 4.0)
          m.size = std::max(m.size, o.size + 8.0);
      }
      marks.push_back(m);
    }
  }
  std::stable_sort(marks.begin(), marks.end(),
                   [](const Mark& a, const Mark& b) { return a.size > b.size; });
  for (const Mark& m : marks)
    PaintMarker(cr, m.style.shape, m.x, m.y, m.size, m.style.colour, false);
}

void PaintViewTitle(cairo_t* cr, const View& view) {
  SetColour(cr, kInk);
  SelectFont(cr, 11, true);
  PaintText(cr, view.title, view.rect.left, view.rect.top - 7, Anchor::kLeft);
}

}  // namespace

Rgb UeColour(const MapScene& scene, std::size_t i) {
  if (scene.links.empty() || scene.placements.size() != 1)
    return kUeNeutral;
  const MapLink& link = scene.links.at(i);
  if (scene.scenario.uavs.size() > 1)
    return UavColour(link.serving_uav);
  return link.los ? kLos : kNlos;
}

void PaintView(cairo_t* cr, const MapScene& scene, const View& view) {
  const Scenario& s = scene.scenario;
  PaintViewBackground(cr, view, s.venue);
  cairo_save(cr);
  // A UAV on the venue's edge is drawn whole: the clip leaves room for half a glyph around.
  const double pad = kUavGlyphSize / 2 + 2;
  cairo_rectangle(cr, view.rect.left - pad, view.rect.top - pad, view.rect.width + 2 * pad,
                  view.rect.height + 2 * pad);
  cairo_clip(cr);
  PaintZones(cr, s, view);
  PaintBuildings(cr, s, view);
  PaintLinks(cr, scene, view);
  PaintUePaths(cr, scene, view);
  PaintFlight(cr, scene, view);
  PaintUes(cr, scene, view);
  PaintUavs(cr, scene, view);
  if (view.IsTop()) {
    PaintUeLabels(cr, scene, view, PaintBuildingLabels(cr, scene, view));
  }
  cairo_restore(cr);
  PaintViewAxes(cr, view, s.venue);
  if (scene.side_views)
    PaintViewTitle(cr, view);
}

}  // namespace rlpos::map
