#include "common/scenario_import/place_options.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <sstream>
#include <vector>

#include "common/config/config_error.h"
#include "common/scenario_generator/generator_options.h"
#include "common/scenario_import/local_projection.h"

namespace rlpos {
namespace {

struct Extension {
  const char* suffix;
  PlaceFormat format;
};

// Longest first: ".osm.pbf" before ".pbf".
const std::vector<Extension>& Extensions() {
  static const std::vector<Extension> list{
      {".osm.pbf", PlaceFormat::kOsm},  {".osm.bz2", PlaceFormat::kOsm},
      {".osm.gz", PlaceFormat::kOsm},   {".geojson", PlaceFormat::kGeoJson},
      {".json", PlaceFormat::kGeoJson}, {".osm", PlaceFormat::kOsm},
      {".pbf", PlaceFormat::kOsm}};
  return list;
}

bool EndsWith(const std::string& text, const std::string& suffix) {
  return text.size() >= suffix.size() &&
         text.compare(text.size() - suffix.size(), suffix.size(), suffix) == 0;
}

std::string Lower(std::string text) {
  std::transform(text.begin(), text.end(), text.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return text;
}

// Numbers separated by `separator`, each a plain decimal (a sign allowed).
std::optional<std::vector<double>> Numbers(const std::string& text, char separator) {
  std::vector<double> out;
  std::stringstream in(text);
  std::string item;
  while (std::getline(in, item, separator)) {
    item.erase(0, item.find_first_not_of(' '));
    item.erase(item.find_last_not_of(' ') + 1);
    if (item.empty() || item.find_first_not_of("+-.0123456789") != std::string::npos)
      return std::nullopt;
    std::size_t used = 0;
    try {
      out.push_back(std::stod(item, &used));
    } catch (const std::exception&) {
      return std::nullopt;
    }
    if (used != item.size() || !std::isfinite(out.back()))
      return std::nullopt;
  }
  if (!text.empty() && text.back() == separator)
    return std::nullopt;
  return out;
}

bool ValidLatLon(double lat, double lon) {
  return lat >= -85 && lat <= 85 && lon >= -180 && lon <= 180;
}

void CheckSide(double side, const std::string& option) {
  if (!(side >= kMinPlaceVenueSide && side <= kMaxPlaceVenueSide)) {
    std::ostringstream out;
    out << "a venue side must be " << kMinPlaceVenueSide << " to " << kMaxPlaceVenueSide
        << " m, got " << side << " m";
    throw ConfigError(option, out.str());
  }
}

}  // namespace

PlaceFormat ParsePlaceFormat(const std::string& text) {
  if (text == "osm")
    return PlaceFormat::kOsm;
  if (text == "geojson")
    return PlaceFormat::kGeoJson;
  throw ConfigError("--from", "unknown format \"" + text + "\" (known: osm, geojson, rlpos3)");
}

std::string PlaceFormatName(PlaceFormat format) {
  return format == PlaceFormat::kOsm ? "osm" : "geojson";
}

PlaceFormat PlaceFormatOfFile(const std::string& file) {
  const std::string name = Lower(std::filesystem::path(file).filename().string());
  for (const auto& e : Extensions()) {
    if (EndsWith(name, e.suffix))
      return e.format;
  }
  throw ConfigError::AboutFile(
      "unknown extension: expected .osm, .osm.pbf, .pbf, .osm.gz or .osm.bz2 (OpenStreetMap), "
      ".geojson or .json (GeoJSON)");
}

std::string PlaceFileStem(const std::string& file) {
  const std::string name = std::filesystem::path(file).filename().string();
  const std::string lower = Lower(name);
  for (const auto& e : Extensions()) {
    if (EndsWith(lower, e.suffix))
      return name.substr(0, name.size() - std::string(e.suffix).size());
  }
  return name;
}

LonLat ParsePlaceCenter(const std::string& text) {
  const auto v = Numbers(text, ',');
  if (!v || v->size() != 2 || !ValidLatLon((*v)[0], (*v)[1])) {
    throw ConfigError("--center",
                      "expected LAT,LON in degrees (latitude first, within +-85), "
                      "e.g. 60.1695,24.9521; got \"" +
                          text + "\"");
  }
  return {(*v)[1], (*v)[0]};
}

VenueSize ParseVenueSize(const std::string& text) {
  const std::string lower = Lower(text);
  const auto v = Numbers(lower, 'x');
  if (!v || v->empty() || v->size() > 2)
    throw ConfigError("--size", "expected WxD in metres (e.g. 400x300), got \"" + text + "\"");
  const VenueSize size{(*v)[0], v->size() == 2 ? (*v)[1] : (*v)[0]};
  CheckSide(size.width, "--size");
  CheckSide(size.depth, "--size");
  return size;
}

GeoBox ParsePlaceBbox(const std::string& text) {
  const auto v = Numbers(text, ',');
  if (!v || v->size() != 4 || !ValidLatLon((*v)[1], (*v)[0]) || !ValidLatLon((*v)[3], (*v)[2]) ||
      (*v)[0] >= (*v)[2] || (*v)[1] >= (*v)[3]) {
    throw ConfigError("--bbox",
                      "expected MINLON,MINLAT,MAXLON,MAXLAT in degrees, minima below "
                      "maxima (e.g. 24.9460,60.1670,24.9530,60.1710); got \"" +
                          text + "\"");
  }
  return {(*v)[0], (*v)[1], (*v)[2], (*v)[3]};
}

int ResolvedUeCount(const PlaceImportOptions& o) {
  return o.ues ? *o.ues : DefaultUeCount(GeneratorStyle::kUrban, o.uavs);
}

PlaceVenue ResolvePlaceVenue(const PlaceImportOptions& o) {
  if (o.uavs < 1 || o.uavs > kMaxGeneratedUavs) {
    throw ConfigError("--uavs", "expected 1 to " + std::to_string(kMaxGeneratedUavs) +
                                    " UAVs, got " + std::to_string(o.uavs));
  }
  const int ues = ResolvedUeCount(o);
  if (ues < 1 || ues > kMaxGeneratedUes) {
    throw ConfigError("--ues", "expected 1 to " + std::to_string(kMaxGeneratedUes) + " UEs, got " +
                                   std::to_string(ues));
  }
  if (o.ue_groups < 0 || o.ue_groups > ues) {
    throw ConfigError("--ue-groups", "expected 0 (no groups) to the UE count (" +
                                         std::to_string(ues) + "), got " +
                                         std::to_string(o.ue_groups));
  }
  if (!(o.heights.level_height > 0 && o.heights.level_height <= 10))
    throw ConfigError("--level-height", "expected a level height above 0 and at most 10 m");
  if (!(o.heights.default_height > 0 && o.heights.default_height <= kMaxBuildingHeight))
    throw ConfigError("--default-height", "expected a height above 0 and at most 1000 m");
  if (o.bbox && (o.center || o.size))
    throw ConfigError("--bbox", "give either --bbox or --center with --size, not both");
  if (o.bbox) {
    const GeoBox& b = *o.bbox;
    const LonLat center{(b.min_lon + b.max_lon) / 2, (b.min_lat + b.max_lat) / 2};
    const LocalProjection projection(center);
    const double width = std::round(projection.Forward({b.max_lon, center.lat}).x -
                                    projection.Forward({b.min_lon, center.lat}).x);
    const double depth = std::round(projection.Forward({center.lon, b.max_lat}).y -
                                    projection.Forward({center.lon, b.min_lat}).y);
    CheckSide(width, "--bbox");
    CheckSide(depth, "--bbox");
    return {center, {width, depth}};
  }
  if (!o.center)
    throw ConfigError("--center", "the venue needs --center LAT,LON with --size WxD, or --bbox");
  if (!o.size)
    throw ConfigError("--size", "--center needs --size WxD (metres)");
  CheckSide(o.size->width, "--size");
  CheckSide(o.size->depth, "--size");
  return {*o.center, *o.size};
}

}  // namespace rlpos
