// The legend: what each mark means (UEs by LoS or by UAV, links, UAVs or the positioners'
// markers, the flight, the zone) and the buildings' height scale. Then the title above the views.
#include <vector>

#include "worker/map/map_painter.h"

namespace rlpos::map {
namespace {

constexpr double kRow = 19;
constexpr double kPad = 10;
constexpr double kHeightBar = 42;  // the building height scale: title, bar, ticks
constexpr double kFont = 10;

enum class Symbol { kUe, kLine, kDashedLine, kUav, kPlacement, kFlight, kZone, kDemand };

struct Entry {
  Symbol symbol;
  std::string text;
  Rgb colour = kInk;
  MarkerShape shape = MarkerShape::kCircle;
};

std::string Point(const Vec3& p) {
  return "(" + ShortNumber(p.x) + ", " + ShortNumber(p.y) + ", " + ShortNumber(p.z) + ")";
}

std::string LosText(const MapPlacement& p, std::size_t n_ues) {
  return p.n_los < 0 ? "" : ", LoS " + std::to_string(p.n_los) + "/" + std::to_string(n_ues);
}

void AddUeEntries(const MapScene& scene, std::vector<Entry>& out) {
  const Scenario& s = scene.scenario;
  const bool links = !scene.links.empty() && scene.placements.size() == 1;
  if (links && s.uavs.size() == 1) {
    out.push_back({Symbol::kUe, "UE in LoS of the UAV", kLos});
    out.push_back({Symbol::kUe, "UE in NLoS (a building in the way)", kNlos});
  } else if (links) {
    for (std::size_t u = 0; u < s.uavs.size(); ++u)
      out.push_back(
          {Symbol::kUe, "UE served by " + s.uavs[u].name, UavColour(static_cast<int>(u))});
  } else {
    out.push_back({Symbol::kUe, "UE", kUeNeutral});
  }
  out.push_back({Symbol::kDemand, "UE demand (Mbit/s)"});
  if (links) {
    out.push_back({Symbol::kLine, "LoS link to the serving UAV"});
    out.push_back({Symbol::kDashedLine, "NLoS link"});
  }
}

void AddUavEntries(const MapScene& scene, std::vector<Entry>& out) {
  const Scenario& s = scene.scenario;
  if (scene.placements.size() == 1) {
    const MapPlacement& p = scene.placements.front();
    for (std::size_t u = 0; u < p.positions.size(); ++u) {
      const std::string name = s.uavs.size() > 1 ? s.uavs[u].name : "UAV";
      out.push_back({Symbol::kUav, name + " " + Point(p.positions[u]),
                     s.uavs.size() > 1 ? UavColour(static_cast<int>(u)) : kInk});
    }
    return;
  }
  for (std::size_t k = 0; k < scene.placements.size(); ++k) {
    const PlacementStyle style = PlacementStyleOf(static_cast<int>(k));
    const MapPlacement& p = scene.placements[k];
    // One UAV: where it is (the top view hides its height). Several: too long for a line.
    const std::string where = p.positions.size() == 1 ? " " + Point(p.positions.front()) : "";
    out.push_back({Symbol::kPlacement, p.label + where + LosText(p, s.ues.size()), style.colour,
                   style.shape});
  }
}

std::vector<Entry> Entries(const MapScene& scene) {
  std::vector<Entry> out;
  AddUeEntries(scene, out);
  AddUavEntries(scene, out);
  if (!scene.ue_paths.empty())
    out.push_back({Symbol::kLine, scene.ue_paths_label, kUePath});
  if (!scene.flight.empty())
    out.push_back({Symbol::kFlight, scene.flight_label, kFlight});
  const Box& z = scene.scenario.uavs.front().zone;
  out.push_back({Symbol::kZone,
                 "UAV zone (z " + ShortNumber(z.zmin) + "-" + ShortNumber(z.zmax) + " m)", kZone});
  return out;
}

void PaintSymbol(cairo_t* cr, const Entry& e, double x, double y) {
  const double dashes[] = {5.0, 3.5};
  cairo_save(cr);
  switch (e.symbol) {
    case Symbol::kUe:
      PaintMarker(cr, MarkerShape::kCircle, x + 12, y, kUeMarkerSize, e.colour, true);
      break;
    case Symbol::kUav:
      PaintUavGlyph(cr, x + 12, y, 18, e.colour);
      break;
    case Symbol::kPlacement:
      PaintMarker(cr, e.shape, x + 12, y, kPlacementMarkerSize, e.colour, false);
      break;
    case Symbol::kDemand:
      SelectFont(cr, kFont);
      SetColour(cr, kInk);
      PaintText(cr, "58.5", x + 12, y + 3, Anchor::kCentre);
      break;
    case Symbol::kLine:
    case Symbol::kDashedLine:
    case Symbol::kFlight:
    case Symbol::kZone:
      SetColour(cr, e.colour);
      cairo_set_line_width(cr, e.symbol == Symbol::kZone ? 1.4 : 1.5);
      if (e.symbol == Symbol::kDashedLine || e.symbol == Symbol::kZone)
        cairo_set_dash(cr, dashes, 2, 0);
      cairo_move_to(cr, x, y), cairo_line_to(cr, x + 24, y);
      cairo_stroke(cr);
      if (e.symbol == Symbol::kFlight) {
        for (double dx : {0.0, 8.0, 16.0, 24.0})
          cairo_new_sub_path(cr), cairo_arc(cr, x + dx, y, 1.8, 0, 6.2832);
        cairo_fill(cr);
      }
      break;
  }
  cairo_restore(cr);
}

// The buildings' colour ramp from the ground to the venue's height limit.
void PaintHeightScale(cairo_t* cr, const Venue& venue, double left, double top, double width) {
  SetColour(cr, kInk);
  SelectFont(cr, kFont);
  PaintText(cr, "building height (m)", left, top + 10, Anchor::kLeft);
  const double bar_top = top + 16, bar_height = 10;
  const int steps = 60;
  for (int k = 0; k < steps; ++k) {
    SetColour(cr, BuildingColour(venue.height * (k + 0.5) / steps, venue.height));
    cairo_rectangle(cr, left + width * k / steps, bar_top, width / steps + 0.3, bar_height);
    cairo_fill(cr);
  }
  SetColour(cr, kInk);
  cairo_set_line_width(cr, 0.8);
  cairo_rectangle(cr, left, bar_top, width, bar_height);
  cairo_stroke(cr);
  SelectFont(cr, kFont);
  for (double f : {0.0, 0.25, 0.5, 0.75, 1.0}) {
    const double x = left + width * f;
    cairo_move_to(cr, x, bar_top + bar_height), cairo_line_to(cr, x, bar_top + bar_height + 3);
    cairo_stroke(cr);
    PaintText(cr, ShortNumber(venue.height * f), x, bar_top + bar_height + 13, Anchor::kCentre);
  }
}

}  // namespace

double LegendHeight(const MapScene& scene) {
  const double scale = scene.scenario.buildings.empty() ? 0 : 6 + kHeightBar;
  return 2 * kPad + kRow * static_cast<double>(Entries(scene).size()) + scale;
}

void PaintLegend(cairo_t* cr, const MapScene& scene, const Rect& box) {
  SetColour(cr, kBackground);
  cairo_rectangle(cr, box.left, box.top, box.width, box.height);
  cairo_fill_preserve(cr);
  SetColour(cr, kInk);
  cairo_set_line_width(cr, 0.8);
  cairo_stroke(cr);
  double y = box.top + kPad + kRow / 2;
  for (const Entry& e : Entries(scene)) {
    PaintSymbol(cr, e, box.left + kPad, y);
    SetColour(cr, kInk);
    SelectFont(cr, kFont);
    PaintText(cr, e.text, box.left + kPad + 34, y + 3.5, Anchor::kLeft);
    y += kRow;
  }
  if (!scene.scenario.buildings.empty())
    PaintHeightScale(cr, scene.scenario.venue, box.left + kPad, y - kRow / 2 + 6,
                     box.width - 2 * kPad - 8);
}

void PaintTitle(cairo_t* cr, const MapScene& scene, const MapLayout& layout) {
  const Scenario& s = scene.scenario;
  const double left = layout.top.rect.left;
  SetColour(cr, kInk);
  SelectFont(cr, 15, true);
  PaintText(cr, "Scenario " + s.name, left, layout.title_top + 14, Anchor::kLeft);
  std::string sub;
  if (scene.placements.size() == 1) {
    const MapPlacement& p = scene.placements.front();
    sub = p.label;
    if (p.n_los >= 0)
      sub += ": " + std::to_string(p.n_los) + " of " + std::to_string(s.ues.size()) +
             " UEs in LoS of their UAV";
  } else {
    sub = std::to_string(scene.placements.size()) + " positioners' placements";
  }
  sub += "; venue " + ShortNumber(s.venue.width) + " x " + ShortNumber(s.venue.depth) + " m, " +
         std::to_string(s.buildings.size()) + " buildings, " + std::to_string(s.ues.size()) +
         " UEs";
  SelectFont(cr, 11);
  PaintText(cr, sub, left, layout.title_top + 32, Anchor::kLeft);
}

}  // namespace rlpos::map
