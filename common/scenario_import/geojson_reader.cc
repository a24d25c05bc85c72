#include "common/scenario_import/geojson_reader.h"

#include <algorithm>

#include "common/config/config_error.h"
#include "common/config/object_reader.h"
#include "common/scenario/scenario_parser.h"

namespace rlpos {
namespace {

using nlohmann::json;

struct ExtentBuilder {
  std::optional<GeoBox> box;
  void Add(const LonLat& p) {
    if (!box) {
      box = GeoBox{p.lon, p.lat, p.lon, p.lat};
      return;
    }
    box->Extend(p);
  }
};

LonLat ReadPosition(const json& v, const std::string& path) {
  if (!v.is_array() || v.size() < 2 || v.size() > 3 || !v[0].is_number() || !v[1].is_number())
    throw ConfigError(path, "expected [longitude, latitude] in degrees");
  const LonLat p{v[0].get<double>(), v[1].get<double>()};
  if (p.lon < -180 || p.lon > 180 || p.lat < -90 || p.lat > 90) {
    throw ConfigError(path,
                      "not a longitude and latitude (longitude first, in [-180, 180]; "
                      "latitude in [-90, 90])");
  }
  return p;
}

std::vector<LonLat> ReadLine(const json& v, const std::string& path, ExtentBuilder& extent) {
  if (!v.is_array())
    throw ConfigError(path, "expected an array of positions");
  std::vector<LonLat> line;
  for (std::size_t i = 0; i < v.size(); ++i) {
    line.push_back(ReadPosition(v[i], JoinPath(path, i)));
    extent.Add(line.back());
  }
  return line;
}

// A property as the import's tags hold it: text as is, anything else as JSON writes it;
// nullopt when it is absent or null.
std::optional<std::string> PropertyText(const json& properties, const std::string& key) {
  if (!properties.contains(key) || properties.at(key).is_null())
    return std::nullopt;
  const json& v = properties.at(key);
  return v.is_string() ? v.get<std::string>() : v.dump();
}

BuildingRole RoleOfProperties(const json& properties) {
  const auto building = PropertyText(properties, "building");
  const auto part = PropertyText(properties, "building:part");
  return RoleOf(building ? building->c_str() : nullptr, part ? part->c_str() : nullptr);
}

void ReadTags(const json& properties, PlaceFeature& feature) {
  for (const auto& key : PlaceTagKeys()) {
    if (auto text = PropertyText(properties, key))
      feature.tags[key] = std::move(*text);
  }
}

class GeoJsonReader {
 public:
  GeoJsonReader(const GeoBox& area, PlaceData& data) : area_(area), data_(data) {}

  void Read(const json& doc) {
    if (!doc.is_object() || !doc.contains("type") || doc.at("type") != "FeatureCollection")
      throw ConfigError("/type", "expected a GeoJSON FeatureCollection");
    if (!doc.contains("features") || !doc.at("features").is_array())
      throw ConfigError("/features", "expected an array of features");
    const json& features = doc.at("features");
    bool tagged = false;
    for (const auto& f : features) {
      const json* props = Properties(f);
      tagged =
          tagged || (props && (props->contains("building") || props->contains("building:part")));
    }
    for (std::size_t i = 0; i < features.size(); ++i)
      ReadFeature(features[i], JoinPath("/features", i), i, tagged);
    data_.extent = extent_.box;
    // RFC 7946's optional bbox says what the collection covers (with altitudes: 6 numbers,
    // the minima first).
    if (extent_.box && doc.contains("bbox")) {
      const json& b = doc.at("bbox");
      if (!b.is_array() || (b.size() != 4 && b.size() != 6) ||
          !std::all_of(b.begin(), b.end(), [](const json& v) { return v.is_number(); })) {
        throw ConfigError("/bbox", "expected [west, south, east, north] in degrees");
      }
      const std::size_t max = b.size() / 2;
      data_.extent = GeoBox{b[0].get<double>(), b[1].get<double>(), b[max].get<double>(),
                            b[max + 1].get<double>()};
    }
  }

 private:
  static const json* Properties(const json& feature) {
    if (!feature.is_object() || !feature.contains("properties"))
      return nullptr;
    const json& p = feature.at("properties");
    return p.is_object() ? &p : nullptr;
  }

  void ReadFeature(const json& f, const std::string& path, std::size_t index, bool tagged) {
    if (!f.is_object() || !f.contains("type") || f.at("type") != "Feature")
      throw ConfigError(JoinPath(path, "type"), "expected a Feature");
    if (!f.contains("geometry") || f.at("geometry").is_null())
      return;  // a feature without a place
    const json& g = f.at("geometry");
    const std::string gpath = JoinPath(path, "geometry");
    if (!g.is_object() || !g.contains("type") || !g.at("type").is_string() ||
        !g.contains("coordinates")) {
      throw ConfigError(gpath, "expected a geometry object with type and coordinates");
    }
    const std::string type = g.at("type").get<std::string>();
    const json& coords = g.at("coordinates");
    const std::string cpath = JoinPath(gpath, "coordinates");
    const json* props = Properties(f);
    if (f.contains("properties") && !f.at("properties").is_null() && !props)
      throw ConfigError(JoinPath(path, "properties"), "expected an object");
    const json empty = json::object();
    const json& p = props ? *props : empty;
    if (type == "LineString" || type == "MultiLineString") {
      ReadStreets(type, coords, cpath, p);
    } else if (type == "Polygon" || type == "MultiPolygon") {
      PlaceFeature feature;
      feature.source = path;
      feature.id = "feature/" + std::to_string(index);
      ReadPolygons(type, coords, cpath, feature);
      const BuildingRole role = RoleOfProperties(p);
      if (tagged && role == BuildingRole::kNone)
        return;
      feature.is_part = role == BuildingRole::kPart;
      ReadTags(p, feature);
      AddBuilding(std::move(feature));
    } else if (type == "Point" || type == "MultiPoint") {
      // Nothing a building or a street is made of, but part of the data's extent.
      ReadLine(type == "Point" ? json::array({coords}) : coords, cpath, extent_);
    }
  }

  // A line or lines; those of a highway near the area are streets.
  void ReadStreets(const std::string& type, const json& coords, const std::string& cpath,
                   const json& p) {
    std::vector<std::vector<LonLat>> lines;
    if (type == "LineString") {
      lines.push_back(ReadLine(coords, cpath, extent_));
    } else {
      if (!coords.is_array())
        throw ConfigError(cpath, "expected an array of lines");
      for (std::size_t i = 0; i < coords.size(); ++i)
        lines.push_back(ReadLine(coords[i], JoinPath(cpath, i), extent_));
    }
    if (!p.contains("highway"))
      return;
    for (auto& line : lines) {
      if (line.size() >= 2 && Near(line))
        data_.streets.push_back(std::move(line));
    }
  }

  void ReadPolygons(const std::string& type, const json& coords, const std::string& cpath,
                    PlaceFeature& feature) {
    if (type == "Polygon") {
      feature.polygons.push_back(ReadPolygon(coords, cpath, feature));
      return;
    }
    if (!coords.is_array())
      throw ConfigError(cpath, "expected an array of polygons");
    for (std::size_t i = 0; i < coords.size(); ++i)
      feature.polygons.push_back(ReadPolygon(coords[i], JoinPath(cpath, i), feature));
  }

  // Keeps a building with a polygon near the area, warning about the rings it closed.
  void AddBuilding(PlaceFeature feature) {
    bool near = false;
    for (const auto& polygon : feature.polygons)
      near = near || Near(polygon.outer);
    if (!near)
      return;
    if (feature.rings_repaired > 0) {
      data_.warnings.push_back({feature.source, std::to_string(feature.rings_repaired) +
                                                    " ring(s) not closed: closed from the last "
                                                    "position to the first"});
    }
    data_.features.push_back(std::move(feature));
  }

  GeoPolygon ReadPolygon(const json& v, const std::string& path, PlaceFeature& feature) {
    if (!v.is_array() || v.empty())
      throw ConfigError(path, "expected a polygon: an array of rings, the outer ring first");
    GeoPolygon polygon;
    for (std::size_t i = 0; i < v.size(); ++i) {
      GeoRing ring = ReadLine(v[i], JoinPath(path, i), extent_);
      // RFC 7946 repeats the first position at the end; a ring that does not is closed here.
      const bool closed = ring.size() > 1 && ring.front().lon == ring.back().lon &&
                          ring.front().lat == ring.back().lat;
      if (closed)
        ring.pop_back();
      else
        ++feature.rings_repaired;
      if (i == 0)
        polygon.outer = std::move(ring);
      else
        polygon.holes.push_back(std::move(ring));
    }
    return polygon;
  }

  bool Near(const std::vector<LonLat>& line) const {
    ExtentBuilder extent;
    for (const auto& p : line)
      extent.Add(p);
    return extent.box && extent.box->Meets(area_);
  }

  GeoBox area_;
  PlaceData& data_;
  ExtentBuilder extent_;
};

}  // namespace

PlaceData ReadGeoJsonFile(const std::string& file, const GeoBox& area) {
  const json doc = ReadJsonFile(file);
  PlaceData data;
  GeoJsonReader(area, data).Read(doc);
  return data;
}

}  // namespace rlpos
