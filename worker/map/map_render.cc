#include "worker/map/map_render.h"

#include <cairo-svg.h>
#include <cairo.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <map>
#include <stdexcept>

#include "common/config/config_error.h"
#include "worker/map/map_painter.h"

namespace rlpos::map {
namespace {

cairo_status_t AppendBytes(void* closure, const unsigned char* data, unsigned int length) {
  static_cast<std::string*>(closure)->append(reinterpret_cast<const char*>(data), length);
  return CAIRO_STATUS_SUCCESS;
}

void Paint(cairo_t* cr, const MapScene& scene, const MapLayout& layout) {
  SetColour(cr, kBackground);
  cairo_paint(cr);
  PaintTitle(cr, scene, layout);
  PaintView(cr, scene, layout.top);
  if (layout.side) {
    PaintView(cr, scene, layout.xz);
    PaintView(cr, scene, layout.yz);
  }
  PaintLegend(cr, scene, layout.legend);
}

void Check(cairo_status_t status, const char* what) {
  if (status != CAIRO_STATUS_SUCCESS)
    throw std::runtime_error(std::string("cannot draw the map (") + what +
                             "): " + cairo_status_to_string(status));
}

// Cairo names the SVG's groups after a counter of every surface the process has made
// ("surface745"): renumbered in order of appearance, the same map is the same bytes however
// many were drawn before it.
std::string RenumberSurfaces(const std::string& svg) {
  static const std::string kPrefix = "surface";
  std::map<std::string, std::string> renamed;
  std::string out;
  out.reserve(svg.size());
  std::size_t at = 0;
  for (std::size_t found; (found = svg.find(kPrefix, at)) != std::string::npos;) {
    std::size_t end = found + kPrefix.size();
    while (end < svg.size() && std::isdigit(static_cast<unsigned char>(svg[end])))
      ++end;
    out.append(svg, at, found - at);
    const std::string number = svg.substr(found + kPrefix.size(), end - found - kPrefix.size());
    if (number.empty()) {
      out += kPrefix;
    } else {
      const auto it = renamed.emplace(number, std::to_string(renamed.size() + 1)).first;
      out += kPrefix + it->second;
    }
    at = end;
  }
  out.append(svg, at, std::string::npos);
  return out;
}

std::string RenderSvg(const MapScene& scene, const MapLayout& layout) {
  std::string bytes;
  cairo_surface_t* surface =
      cairo_svg_surface_create_for_stream(AppendBytes, &bytes, layout.width, layout.height);
  cairo_t* cr = cairo_create(surface);
  Paint(cr, scene, layout);
  const cairo_status_t drawn = cairo_status(cr);
  cairo_destroy(cr);
  cairo_surface_finish(surface);  // writes the document's end
  const cairo_status_t written = cairo_surface_status(surface);
  cairo_surface_destroy(surface);
  Check(drawn, "drawing");
  Check(written, "SVG");
  return RenumberSurfaces(bytes);
}

std::string RenderPng(const MapScene& scene, const MapLayout& layout) {
  const int width = static_cast<int>(std::ceil(layout.width * kPngPixelsPerPoint));
  const int height = static_cast<int>(std::ceil(layout.height * kPngPixelsPerPoint));
  cairo_surface_t* surface = cairo_image_surface_create(CAIRO_FORMAT_RGB24, width, height);
  cairo_t* cr = cairo_create(surface);
  cairo_scale(cr, kPngPixelsPerPoint, kPngPixelsPerPoint);
  Paint(cr, scene, layout);
  const cairo_status_t drawn = cairo_status(cr);
  cairo_destroy(cr);
  std::string bytes;
  const cairo_status_t written = cairo_surface_write_to_png_stream(surface, AppendBytes, &bytes);
  cairo_surface_destroy(surface);
  Check(drawn, "drawing");
  Check(written, "PNG");
  return bytes;
}

}  // namespace

MapFormat MapFormatOf(const std::string& file, const std::string& what) {
  const std::size_t dot = file.find_last_of('.');
  std::string ext = dot == std::string::npos ? "" : file.substr(dot + 1);
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  if (ext == "png")
    return MapFormat::kPng;
  if (ext == "svg")
    return MapFormat::kSvg;
  throw ConfigError(what, "\"" + file + "\": the map's file name must end in .png or .svg");
}

MapLayout LayoutOf(const MapScene& scene) {
  return ComputeLayout(scene, LegendHeight(scene));
}

std::string RenderMap(const MapScene& scene, MapFormat format) {
  if (scene.placements.empty())
    throw std::invalid_argument("a map needs at least one placement");
  const MapLayout layout = LayoutOf(scene);
  return format == MapFormat::kPng ? RenderPng(scene, layout) : RenderSvg(scene, layout);
}

}  // namespace rlpos::map
