#include <cmath>
#include <cstdio>

#include "worker/map/map_painter.h"

namespace rlpos::map {
namespace {

// The path of a regular polygon of `n` corners, one at angle `start` (radians, y down).
void PolygonPath(cairo_t* cr, double x, double y, double radius, int n, double start) {
  for (int k = 0; k < n; ++k) {
    const double a = start + 2 * M_PI * k / n;
    const double px = x + radius * std::cos(a), py = y + radius * std::sin(a);
    k == 0 ? cairo_move_to(cr, px, py) : cairo_line_to(cr, px, py);
  }
  cairo_close_path(cr);
}

void StarPath(cairo_t* cr, double x, double y, double radius) {
  for (int k = 0; k < 10; ++k) {
    const double a = -M_PI / 2 + M_PI * k / 5;
    const double r = k % 2 == 0 ? radius : radius * 0.45;
    const double px = x + r * std::cos(a), py = y + r * std::sin(a);
    k == 0 ? cairo_move_to(cr, px, py) : cairo_line_to(cr, px, py);
  }
  cairo_close_path(cr);
}

// Plus and cross are strokes, not areas: drawn as two thick bars.
void BarsPath(cairo_t* cr, double x, double y, double r, bool diagonal) {
  const double d = diagonal ? r * 0.75 : r;
  if (diagonal) {
    cairo_move_to(cr, x - d, y - d), cairo_line_to(cr, x + d, y + d);
    cairo_move_to(cr, x - d, y + d), cairo_line_to(cr, x + d, y - d);
  } else {
    cairo_move_to(cr, x - d, y), cairo_line_to(cr, x + d, y);
    cairo_move_to(cr, x, y - d), cairo_line_to(cr, x, y + d);
  }
}

void ShapePath(cairo_t* cr, MarkerShape shape, double x, double y, double r) {
  switch (shape) {
    case MarkerShape::kCircle:
      cairo_new_sub_path(cr), cairo_arc(cr, x, y, r, 0, 2 * M_PI);
      break;
    case MarkerShape::kSquare:
      cairo_rectangle(cr, x - r * 0.85, y - r * 0.85, r * 1.7, r * 1.7);
      break;
    case MarkerShape::kTriangleUp:
      PolygonPath(cr, x, y + r * 0.15, r * 1.1, 3, -M_PI / 2);
      break;
    case MarkerShape::kDiamond:
      PolygonPath(cr, x, y, r * 1.1, 4, -M_PI / 2);
      break;
    case MarkerShape::kTriangleDown:
      PolygonPath(cr, x, y - r * 0.15, r * 1.1, 3, M_PI / 2);
      break;
    case MarkerShape::kPentagon:
      PolygonPath(cr, x, y, r * 1.05, 5, -M_PI / 2);
      break;
    case MarkerShape::kStar:
      StarPath(cr, x, y, r * 1.25);
      break;
    case MarkerShape::kPlus:
      BarsPath(cr, x, y, r, false);
      break;
    case MarkerShape::kCross:
      BarsPath(cr, x, y, r, true);
      break;
  }
}

}  // namespace

void SetColour(cairo_t* cr, const Rgb& colour, double alpha) {
  if (alpha >= 1.0)
    cairo_set_source_rgb(cr, colour.r, colour.g, colour.b);
  else
    cairo_set_source_rgba(cr, colour.r, colour.g, colour.b, alpha);
}

void PaintMarker(cairo_t* cr, MarkerShape shape, double x, double y, double size, const Rgb& colour,
                 bool filled) {
  const double r = size / 2;
  cairo_save(cr);
  cairo_new_path(cr);
  ShapePath(cr, shape, x, y, r);
  const bool bars = shape == MarkerShape::kPlus || shape == MarkerShape::kCross;
  if (bars) {
    // Ink under the colour: a bar stays visible over any fill.
    cairo_set_line_cap(cr, CAIRO_LINE_CAP_ROUND);
    SetColour(cr, kBackground);
    cairo_set_line_width(cr, size * 0.34);
    cairo_stroke_preserve(cr);
    SetColour(cr, colour);
    cairo_set_line_width(cr, size * 0.2);
    cairo_stroke(cr);
  } else if (filled) {
    SetColour(cr, colour);
    cairo_fill_preserve(cr);
    SetColour(cr, kInk);
    cairo_set_line_width(cr, 0.9);
    cairo_stroke(cr);
  } else {
    SetColour(cr, kBackground, 0.85);
    cairo_set_line_width(cr, 4.2);
    cairo_stroke_preserve(cr);
    SetColour(cr, colour);
    cairo_set_line_width(cr, 2.2);
    cairo_stroke(cr);
  }
  cairo_restore(cr);
}

void PaintUavGlyph(cairo_t* cr, double x, double y, double size, const Rgb& colour) {
  const double arm = size * 0.32, rotor = size * 0.18;
  cairo_save(cr);
  cairo_new_path(cr);
  cairo_set_line_cap(cr, CAIRO_LINE_CAP_ROUND);
  // A white outline first keeps the glyph readable over buildings and links.
  for (int pass = 0; pass < 2; ++pass) {
    SetColour(cr, pass == 0 ? kBackground : colour);
    cairo_set_line_width(cr, pass == 0 ? 5.0 : 2.4);
    cairo_move_to(cr, x - arm, y - arm), cairo_line_to(cr, x + arm, y + arm);
    cairo_move_to(cr, x - arm, y + arm), cairo_line_to(cr, x + arm, y - arm);
    cairo_stroke(cr);
    for (int dx = -1; dx <= 1; dx += 2) {
      for (int dy = -1; dy <= 1; dy += 2) {
        cairo_new_sub_path(cr);
        cairo_arc(cr, x + dx * arm, y + dy * arm, rotor, 0, 2 * M_PI);
      }
    }
    cairo_set_line_width(cr, pass == 0 ? 4.0 : 1.6);
    cairo_stroke(cr);
  }
  cairo_rectangle(cr, x - size * 0.12, y - size * 0.12, size * 0.24, size * 0.24);
  SetColour(cr, colour);
  cairo_fill(cr);
  cairo_restore(cr);
}

bool TextBox::Overlaps(const TextBox& o, double pad) const {
  return left < o.left + o.width + pad && o.left < left + width + pad &&
         top < o.top + o.height + pad && o.top < top + height + pad;
}

void SelectFont(cairo_t* cr, double size, bool bold) {
  cairo_select_font_face(cr, kFontFamily, CAIRO_FONT_SLANT_NORMAL,
                         bold ? CAIRO_FONT_WEIGHT_BOLD : CAIRO_FONT_WEIGHT_NORMAL);
  cairo_set_font_size(cr, size);
}

TextBox MeasureText(cairo_t* cr, const std::string& text, double x, double y, Anchor anchor) {
  cairo_text_extents_t ext;
  cairo_text_extents(cr, text.c_str(), &ext);
  cairo_font_extents_t font;
  cairo_font_extents(cr, &font);
  const double width = ext.x_advance;
  const double left = anchor == Anchor::kLeft     ? x
                      : anchor == Anchor::kCentre ? x - width / 2
                                                  : x - width;
  return {left, y - font.ascent * 0.8, width, font.ascent * 0.8 + font.descent * 0.6};
}

void PaintText(cairo_t* cr, const std::string& text, double x, double y, Anchor anchor) {
  const TextBox box = MeasureText(cr, text, x, y, anchor);
  cairo_move_to(cr, box.left, y);
  cairo_show_text(cr, text.c_str());
  cairo_new_path(cr);
}

void PaintHaloText(cairo_t* cr, const std::string& text, double x, double y, Anchor anchor,
                   const Rgb& halo) {
  // A box rather than an outline of the glyphs: an SVG then holds each glyph once.
  const TextBox box = MeasureText(cr, text, x, y, anchor);
  cairo_save(cr);
  cairo_rectangle(cr, box.left - 1.5, box.top - 1, box.width + 3, box.height + 2);
  SetColour(cr, halo, 0.8);
  cairo_fill(cr);
  cairo_restore(cr);
  PaintText(cr, text, x, y, anchor);
}

std::string ShortNumber(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.1f", value);
  std::string s = text;
  if (s.size() > 2 && s.compare(s.size() - 2, 2, ".0") == 0)
    s.resize(s.size() - 2);
  return s == "-0" ? "0" : s;
}

}  // namespace rlpos::map
