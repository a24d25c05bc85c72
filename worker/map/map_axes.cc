#include <cmath>

#include "worker/map/map_painter.h"

namespace rlpos::map {
namespace {

double Extent(const Venue& venue, Axis axis) {
  return axis == Axis::kX ? venue.width : axis == Axis::kY ? venue.depth : venue.height;
}

const char* AxisTitle(Axis axis) {
  return axis == Axis::kX ? "x (m)" : axis == Axis::kY ? "y (m)" : "z (m)";
}

// A round step giving at most 10 intervals over `extent` metres.
double TickStep(double extent) {
  for (double step : {5.0, 10.0, 20.0, 25.0, 50.0, 100.0, 200.0, 250.0, 500.0}) {
    if (extent / step <= 10.0)
      return step;
  }
  return std::pow(10.0, std::ceil(std::log10(extent / 10.0)));
}

template <typename F>
void ForEachTick(double extent, F&& f) {
  const double step = TickStep(extent);
  for (int k = 0; k * step <= extent + 1e-9; ++k)
    f(k * step);
}

}  // namespace

void PaintViewBackground(cairo_t* cr, const View& view, const Venue& venue) {
  const Rect& r = view.rect;
  cairo_rectangle(cr, r.left, r.top, r.width, r.height);
  SetColour(cr, kGround);
  cairo_fill(cr);
  SetColour(cr, kGrid);
  cairo_set_line_width(cr, 0.6);
  ForEachTick(Extent(venue, view.horizontal), [&](double m) {
    cairo_move_to(cr, r.left + m * view.scale, r.top);
    cairo_line_to(cr, r.left + m * view.scale, r.bottom());
  });
  ForEachTick(Extent(venue, view.vertical), [&](double m) {
    cairo_move_to(cr, r.left, r.bottom() - m * view.scale);
    cairo_line_to(cr, r.right(), r.bottom() - m * view.scale);
  });
  cairo_stroke(cr);
}

void PaintViewAxes(cairo_t* cr, const View& view, const Venue& venue) {
  const Rect& r = view.rect;
  SetColour(cr, kInk);
  cairo_set_line_width(cr, 1.0);
  cairo_rectangle(cr, r.left, r.top, r.width, r.height);
  cairo_stroke(cr);
  SelectFont(cr, 10);
  ForEachTick(Extent(venue, view.horizontal), [&](double m) {
    const double x = r.left + m * view.scale;
    cairo_move_to(cr, x, r.bottom()), cairo_line_to(cr, x, r.bottom() + 4);
    cairo_stroke(cr);
    PaintText(cr, ShortNumber(m), x, r.bottom() + 15, Anchor::kCentre);
  });
  ForEachTick(Extent(venue, view.vertical), [&](double m) {
    const double y = r.bottom() - m * view.scale;
    cairo_move_to(cr, r.left - 4, y), cairo_line_to(cr, r.left, y);
    cairo_stroke(cr);
    PaintText(cr, ShortNumber(m), r.left - 6, y + 3.5, Anchor::kRight);
  });
  SelectFont(cr, 11);
  PaintText(cr, AxisTitle(view.horizontal), r.left + r.width / 2, r.bottom() + 32, Anchor::kCentre);
  cairo_save(cr);
  cairo_translate(cr, r.left - 36, r.top + r.height / 2);
  cairo_rotate(cr, -M_PI / 2);
  PaintText(cr, AxisTitle(view.vertical), 0, 0, Anchor::kCentre);
  cairo_restore(cr);
}

}  // namespace rlpos::map
