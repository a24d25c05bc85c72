#pragma once
// A map as the bytes of a PNG or an SVG file: one drawing (Cairo) onto either surface. The same
// scene gives the same bytes (Cairo writes no date; its text is DejaVu Sans, kFontFamily).
#include <string>

#include "worker/map/map_layout.h"
#include "worker/map/map_scene.h"

namespace rlpos::map {

enum class MapFormat { kPng, kSvg };

// By the file name's extension, .png or .svg (any case). Throws ConfigError naming `what`.
MapFormat MapFormatOf(const std::string& file, const std::string& what);

// Where everything of `scene` goes (the tests find a building's pixels by it).
MapLayout LayoutOf(const MapScene& scene);

// Throws std::runtime_error when Cairo fails.
std::string RenderMap(const MapScene& scene, MapFormat format);

}  // namespace rlpos::map
