// The top view's labels: each building's name and height inside it (turned to fit a narrow one;
// in a footprint, at a point of the shape where it fits), then the UAVs' heights and the UEs'
// demands, each put where it hides no marker and no other label (the first free spot of a few
// around its point).
#include <cmath>
#include <string>
#include <vector>

#include "common/scenario/building_obstacles.h"
#include "worker/map/map_painter.h"
#include "worker/map/map_shapes.h"

namespace rlpos::map {
namespace {

constexpr double kBuildingFont = 10;
constexpr double kUeFont = 10;
constexpr double kUavFont = 10;

struct BuildingLabel {
  std::vector<std::string> lines;
  bool turned = false;  // written bottom to top, along a footprint taller than wide
};

// Where a building's label goes inside it: the label, centred on `at` (metres).
struct Fit {
  BuildingLabel label;
  Point2 at;
};

// Whether `text` is an OpenStreetMap element as an imported building names it: "way/123",
// "relation/45" (common/scenario_import), or "feature/3" (GeoJSON).
bool IsElementId(const std::string& text) {
  for (const char* kind : {"way/", "relation/", "feature/"}) {
    const std::string prefix = kind;
    if (text.size() > prefix.size() && text.compare(0, prefix.size(), prefix) == 0 &&
        text.find_first_not_of("0123456789", prefix.size()) == std::string::npos)
      return true;
  }
  return false;
}

// The first of the label's forms that fits inside the building's ground shape, upright, else
// turned, at the first of its label points where it does; none when it fits nowhere. Each form
// keeps 3 points of room either side and 1 above and below. `name`: BuildingLabelName's, empty
// for the height alone.
bool FitBuildingLabel(cairo_t* cr, const BuildingSpec& b, const std::string& name, double scale,
                      Fit& fit) {
  const std::string height = ShortNumber(b.height) + " m";
  std::vector<std::vector<std::string>> forms = {{name, height}, {name + ", " + height}, {height}};
  if (name.empty())
    forms.erase(forms.begin(), forms.begin() + 2);
  const double line_height = kBuildingFont * 1.25;
  const Footprint shape = GroundShape(b);
  const std::vector<Point2> points = LabelPoints(b);
  for (const auto& lines : forms) {
    double width = 0;
    for (const auto& line : lines)
      width = std::max(width, MeasureText(cr, line, 0, 0, Anchor::kLeft).width);
    const double tall = line_height * static_cast<double>(lines.size());
    for (bool turned : {false, true}) {
      // Half the room it needs, in metres.
      const double half_x = (turned ? tall + 2 : width + 6) / scale / 2;
      const double half_y = (turned ? width + 6 : tall + 2) / scale / 2;
      for (const Point2& p : points) {
        if (RectangleInside(shape, {p.x - half_x, p.y - half_y, p.x + half_x, p.y + half_y})) {
          fit = {{lines, turned}, p};
          return true;
        }
      }
    }
  }
  return false;
}

void PaintBuildingLabel(cairo_t* cr, const BuildingLabel& label, double cx, double cy, bool light) {
  const double line_height = kBuildingFont * 1.25;
  const double n = static_cast<double>(label.lines.size());
  cairo_save(cr);
  cairo_translate(cr, cx, cy);
  if (label.turned)
    cairo_rotate(cr, -M_PI / 2);
  SetColour(cr, light ? kBackground : kInk);
  for (std::size_t k = 0; k < label.lines.size(); ++k) {
    const double y = -n * line_height / 2 + line_height * (static_cast<double>(k) + 0.78);
    PaintText(cr, label.lines[k], 0, y, Anchor::kCentre);
  }
  cairo_restore(cr);
}

TextBox PointBox(double x, double y, double size) {
  return {x - size / 2, y - size / 2, size, size};
}

// Puts `text` near (x, y), clear of `taken` if it can, inside `frame`; returns its box.
struct Segment {
  double x0, y0, x1, y1;
};

// What a label should not cover: markers and other labels (worse), and lines (links, flights).
struct Obstacles {
  std::vector<TextBox> boxes;
  std::vector<Segment> lines;
};

// Whether the segment crosses the box (clipped against it, Liang-Barsky).
bool Crosses(const Segment& s, const TextBox& b) {
  double t0 = 0, t1 = 1;
  const double dx = s.x1 - s.x0, dy = s.y1 - s.y0;
  const double p[] = {-dx, dx, -dy, dy};
  const double q[] = {s.x0 - b.left, b.left + b.width - s.x0, s.y0 - b.top,
                      b.top + b.height - s.y0};
  for (int k = 0; k < 4; ++k) {
    if (p[k] == 0) {
      if (q[k] < 0)
        return false;
      continue;
    }
    const double t = q[k] / p[k];
    if (p[k] < 0)
      t0 = std::max(t0, t);
    else
      t1 = std::min(t1, t);
  }
  return t0 <= t1;
}

int Cost(const TextBox& box, const Obstacles& o) {
  int cost = 0;
  for (const TextBox& t : o.boxes)
    cost += box.Overlaps(t) ? 4 : 0;
  for (const Segment& s : o.lines)
    cost += Crosses(s, box) ? 1 : 0;
  return cost;
}

TextBox PlaceLabel(cairo_t* cr, const std::string& text, double x, double y, double gap,
                   const Obstacles& taken, const Rect& frame) {
  struct Spot {
    double dx, dy;
    Anchor anchor;
  };
  const double h = MeasureText(cr, text, 0, 0, Anchor::kLeft).height;
  const Spot spots[] = {{gap, h / 2 - 1, Anchor::kLeft},
                        {-gap, h / 2 - 1, Anchor::kRight},
                        {0, -gap, Anchor::kCentre},
                        {0, gap + h - 1, Anchor::kCentre},
                        {gap * 0.8, -gap * 0.8, Anchor::kLeft},
                        {-gap * 0.8, -gap * 0.8, Anchor::kRight},
                        {gap * 0.8, gap * 0.8 + h - 2, Anchor::kLeft},
                        {-gap * 0.8, gap * 0.8 + h - 2, Anchor::kRight}};
  TextBox best;
  int best_overlaps = -1;
  for (const Spot& s : spots) {
    const TextBox box = MeasureText(cr, text, x + s.dx, y + s.dy, s.anchor);
    if (box.left < frame.left + 2 || box.left + box.width > frame.right() - 2 ||
        box.top < frame.top + 2 || box.top + box.height > frame.bottom() - 2)
      continue;
    const int overlaps = Cost(box, taken);
    if (best_overlaps < 0 || overlaps < best_overlaps) {
      best = box;
      best_overlaps = overlaps;
      if (overlaps == 0)
        break;
    }
  }
  if (best_overlaps < 0)
    best = MeasureText(cr, text, x + gap, y + h / 2 - 1, Anchor::kLeft);
  return best;
}

void PaintPlaced(cairo_t* cr, const std::string& text, const TextBox& box, const Rgb& colour) {
  cairo_font_extents_t font;
  cairo_font_extents(cr, &font);
  SetColour(cr, colour);
  PaintHaloText(cr, text, box.left, box.top + font.ascent * 0.8, Anchor::kLeft, kBackground);
}

std::vector<TextBox> MarkerBoxes(const MapScene& scene, const View& view) {
  std::vector<TextBox> boxes;
  for (const auto& ue : scene.scenario.ues)
    boxes.push_back(PointBox(view.CanvasX(ue.position), view.CanvasY(ue.position), kUeMarkerSize));
  for (const auto& placement : scene.placements) {
    const double size = scene.placements.size() == 1 ? kUavGlyphSize : kPlacementMarkerSize;
    for (const Vec3& p : placement.positions)
      boxes.push_back(PointBox(view.CanvasX(p), view.CanvasY(p), size));
  }
  return boxes;
}

// The box a building label takes centred on (cx, cy), in the font selected.
TextBox LabelBox(cairo_t* cr, const BuildingLabel& label, double cx, double cy) {
  double width = 0;
  for (const auto& line : label.lines)
    width = std::max(width, MeasureText(cr, line, 0, 0, Anchor::kLeft).width);
  const double tall = kBuildingFont * 1.25 * static_cast<double>(label.lines.size());
  const double w = label.turned ? tall : width, h = label.turned ? width : tall;
  return {cx - w / 2, cy - h / 2, w, h};
}

bool Hides(const TextBox& box, const std::vector<TextBox>& markers) {
  for (const TextBox& m : markers) {
    if (box.Overlaps(m, 0.0))
      return true;
  }
  return false;
}

// The links (one placement) and the flight, as drawn in the view.
std::vector<Segment> Lines(const MapScene& scene, const View& view) {
  std::vector<Segment> lines;
  if (!scene.links.empty() && scene.placements.size() == 1) {
    const Placement& uavs = scene.placements.front().positions;
    for (std::size_t i = 0; i < scene.links.size(); ++i) {
      const Vec3& a = scene.scenario.ues[i].position;
      const Vec3& b = uavs.at(static_cast<std::size_t>(scene.links[i].serving_uav));
      lines.push_back({view.CanvasX(a), view.CanvasY(a), view.CanvasX(b), view.CanvasY(b)});
    }
  }
  for (const FlightPath& path : scene.flight) {
    for (std::size_t k = 1; k < path.points.size(); ++k) {
      const Vec3 &a = path.points[k - 1], &b = path.points[k];
      lines.push_back({view.CanvasX(a), view.CanvasY(a), view.CanvasX(b), view.CanvasY(b)});
    }
  }
  return lines;
}

}  // namespace

std::string BuildingLabelName(const std::string& name) {
  std::string base = name;
  const auto piece = base.rfind(" #");
  if (piece != std::string::npos &&
      base.find_first_not_of("0123456789", piece + 2) == std::string::npos)
    base.erase(piece);
  if (IsElementId(base))
    return "";
  const auto open = base.rfind(" (");
  if (open != std::string::npos && base.back() == ')' &&
      IsElementId(base.substr(open + 2, base.size() - open - 3)))
    return base.substr(0, open) + name.substr(base.size());
  return name;
}

std::vector<TextBox> PaintBuildingLabels(cairo_t* cr, const MapScene& scene, const View& view) {
  const Scenario& s = scene.scenario;
  const std::vector<TextBox> markers = MarkerBoxes(scene, view);
  std::vector<TextBox> boxes;
  SelectFont(cr, kBuildingFont);
  for (const BuildingSpec& b : s.buildings) {
    const std::string name = BuildingLabelName(b.name);
    Fit fit;
    const bool fits = FitBuildingLabel(cr, b, name, view.scale, fit);
    const Point2 at = fits ? fit.at : LabelPoints(b).front();
    const double cx = view.CanvasX({at.x, 0, 0}), cy = view.CanvasY({0, at.y, 0});
    // Inside, unless it would cover a marker or the label of a building it stands in or on.
    const TextBox inside = fits ? LabelBox(cr, fit.label, cx, cy) : TextBox{};
    if (fits && !Hides(inside, markers) && !Hides(inside, boxes)) {
      PaintBuildingLabel(cr, fit.label, cx, cy, BuildingTextIsLight(b.height, s.venue.height));
      boxes.push_back(inside);
      continue;
    }
    // Too small for its label, or a UAV or UE sits where it would go: the label goes beside the
    // building, with a halo, where it hides nothing; a building known only by its element id
    // keeps just its shade (the height scale).
    if (name.empty())
      continue;
    const std::string text = name + ", " + ShortNumber(b.height) + " m";
    Obstacles taken{markers, Lines(scene, view)};
    taken.boxes.insert(taken.boxes.end(), boxes.begin(), boxes.end());
    const double w = (b.xmax - b.xmin) * view.scale, h = (b.ymax - b.ymin) * view.scale;
    const TextBox box = PlaceLabel(cr, text, cx, cy, std::max(w, h) / 2 + 6, taken, view.rect);
    PaintPlaced(cr, text, box, kInk);
    boxes.push_back(box);
  }
  return boxes;
}

void PaintUeLabels(cairo_t* cr, const MapScene& scene, const View& view,
                   std::vector<TextBox> labels) {
  const Scenario& s = scene.scenario;
  Obstacles taken{std::move(labels), Lines(scene, view)};
  for (const TextBox& box : MarkerBoxes(scene, view))
    taken.boxes.push_back(box);
  // The UAVs' heights first (a top view hides them), then the demands.
  if (scene.placements.size() == 1) {
    SelectFont(cr, kUavFont, true);
    const Placement& positions = scene.placements.front().positions;
    for (std::size_t u = 0; u < positions.size(); ++u) {
      const Vec3& p = positions[u];
      const std::string text = (s.uavs.size() > 1 ? s.uavs[u].name + ", " : std::string()) + "z " +
                               ShortNumber(p.z) + " m";
      const TextBox box = PlaceLabel(cr, text, view.CanvasX(p), view.CanvasY(p),
                                     kUavGlyphSize / 2 + 4, taken, view.rect);
      PaintPlaced(cr, text, box, s.uavs.size() > 1 ? UavColour(static_cast<int>(u)) : kInk);
      taken.boxes.push_back(box);
    }
  }
  SelectFont(cr, kUeFont);
  for (const UeSpec& ue : s.ues) {
    const std::string text = ShortNumber(ue.demand_mbps);
    const double x = view.CanvasX(ue.position), y = view.CanvasY(ue.position);
    const TextBox box = PlaceLabel(cr, text, x, y, kUeMarkerSize / 2 + 3, taken, view.rect);
    PaintPlaced(cr, text, box, kInk);
    taken.boxes.push_back(box);
  }
}

}  // namespace rlpos::map
