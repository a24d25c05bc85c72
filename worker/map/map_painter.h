#pragma once
// The drawing steps of a map over Cairo (internal to worker/map): primitives, axes, the views
// and the legend. Every length is in points.
#include <cairo.h>

#include <string>
#include <vector>

#include "worker/map/map_layout.h"
#include "worker/map/map_scene.h"
#include "worker/map/map_style.h"

namespace rlpos::map {

// Primitives (map_primitives.cc).
void SetColour(cairo_t* cr, const Rgb& colour, double alpha = 1.0);
// A marker `size` across centred on (x, y): filled with `colour` and outlined in ink, or (not
// filled) drawn as a thick outline only, so that markers on one spot stay visible.
void PaintMarker(cairo_t* cr, MarkerShape shape, double x, double y, double size, const Rgb& colour,
                 bool filled);
// A quadcopter seen from above, `size` across.
void PaintUavGlyph(cairo_t* cr, double x, double y, double size, const Rgb& colour);

enum class Anchor { kLeft, kCentre, kRight };
struct TextBox {
  double left = 0, top = 0, width = 0, height = 0;
  bool Overlaps(const TextBox& o, double pad = 1.0) const;
};
void SelectFont(cairo_t* cr, double size, bool bold = false);
// The box `text` takes with its baseline at y, anchored at x, in the font selected.
TextBox MeasureText(cairo_t* cr, const std::string& text, double x, double y, Anchor anchor);
void PaintText(cairo_t* cr, const std::string& text, double x, double y, Anchor anchor);
// Text on a translucent box of the background: readable over lines.
void PaintHaloText(cairo_t* cr, const std::string& text, double x, double y, Anchor anchor,
                   const Rgb& halo);
// "58.5", "234", "-3": the shortest form that reads back the same to 0.1.
std::string ShortNumber(double value);

// The frame, grid, ticks and axis titles of a view (map_axes.cc).
void PaintViewBackground(cairo_t* cr, const View& view, const Venue& venue);
void PaintViewAxes(cairo_t* cr, const View& view, const Venue& venue);

// Everything a view shows of the scene (map_view.cc).
void PaintView(cairo_t* cr, const MapScene& scene, const View& view);
// Its buildings, far ones first (map_buildings.cc).
void PaintBuildings(cairo_t* cr, const Scenario& s, const View& view);
// The labels of the top view: buildings (name, height) and UEs (demand) (map_labels.cc).
// Returns the boxes the building labels took.
std::vector<TextBox> PaintBuildingLabels(cairo_t* cr, const MapScene& scene, const View& view);
// What a building's label calls it: its name without the element id an imported building's name
// carries ("Rautatalo (way/34079465)" -> "Rautatalo"); "" for a name that is only an id
// ("way/123", "relation/45", "feature/3", with a piece's " #2"), which is left unlabelled.
std::string BuildingLabelName(const std::string& name);
void PaintUeLabels(cairo_t* cr, const MapScene& scene, const View& view,
                   std::vector<TextBox> taken);

// The legend (map_legend.cc).
double LegendHeight(const MapScene& scene);
void PaintLegend(cairo_t* cr, const MapScene& scene, const Rect& box);
// The title and subtitle above the views.
void PaintTitle(cairo_t* cr, const MapScene& scene, const MapLayout& layout);

// Shared by the view and the legend.
constexpr double kUeMarkerSize = 10;
constexpr double kUavGlyphSize = 22;
constexpr double kPlacementMarkerSize = 14;
// The colour of UE `i`'s marker, and whether its link to the serving UAV is LoS.
Rgb UeColour(const MapScene& scene, std::size_t i);

}  // namespace rlpos::map
