#include "common/scenario/building_settings.h"

#include <sstream>
#include <tuple>
#include <utility>

namespace rlpos {
namespace {

using nlohmann::json;

void ReadX(BuildingSpec& b, const json& v, const std::string& path) {
  std::tie(b.xmin, b.xmax) = ReadInterval(v, path, false);
}
json XJson(const BuildingSpec& b) {
  return {b.xmin, b.xmax};
}
void ReadY(BuildingSpec& b, const json& v, const std::string& path) {
  std::tie(b.ymin, b.ymax) = ReadInterval(v, path, false);
}
json YJson(const BuildingSpec& b) {
  return {b.ymin, b.ymax};
}

void ReadFootprint(BuildingSpec& b, const json& v, const std::string& path) {
  b.SetFootprint({ReadRing(v, path), std::move(b.footprint.holes)});
}
json FootprintJson(const BuildingSpec& b) {
  return RingJson(b.footprint.outer);
}
void ReadHoles(BuildingSpec& b, const json& v, const std::string& path) {
  b.footprint.holes = ReadRings(v, path);
}
json HolesJson(const BuildingSpec& b) {
  return RingsJson(b.footprint.holes);
}

void ReadRooms(BuildingSpec& b, const json& v, const std::string& path) {
  if (!v.is_array() || v.size() != 2 || !v[0].is_number_integer() || !v[1].is_number_integer() ||
      v[0].get<long long>() < 1 || v[1].get<long long>() < 1) {
    throw ConfigError(path, "expected [rooms_x, rooms_y], integers >= 1");
  }
  b.rooms_x = v[0].get<int>();
  b.rooms_y = v[1].get<int>();
}
json RoomsJson(const BuildingSpec& b) {
  return {b.rooms_x, b.rooms_y};
}

// The keys of one shape are written only for that shape, so that a box building's JSON keeps the
// bytes it had before footprints existed.
bool IsBox(const BuildingSpec& b) {
  return !b.HasFootprint();
}
bool HasFootprint(const BuildingSpec& b) {
  return b.HasFootprint();
}
bool HasHoles(const BuildingSpec& b) {
  return !b.footprint.holes.empty();
}
bool StartsAboveGround(const BuildingSpec& b) {
  return b.min_height != 0.0;
}

// Exactly one shape: a box (x and y) or a footprint (with its holes and min_height).
void CheckShape(const BuildingSpec& b, const ObjectReader& reader) {
  if (reader.Has("footprint")) {
    for (const char* key : {"x", "y"}) {
      if (reader.Has(key)) {
        throw ConfigError(reader.PathOf(key),
                          "a building is a box (x and y) or a footprint, not both");
      }
    }
  } else {
    for (const char* key : {"x", "y"}) {
      if (!reader.Has(key)) {
        throw ConfigError(reader.PathOf(key), std::string("is required ([") + key + "min, " + key +
                                                  "max]; or a footprint instead of x, y)");
      }
    }
    if (reader.Has("holes"))
      throw ConfigError(reader.PathOf("holes"), "holes need a footprint");
    if (reader.Has("min_height")) {
      throw ConfigError(reader.PathOf("min_height"),
                        "needs a footprint: a box stands on the ground, as ns-3's buildings do");
    }
  }
  if (b.min_height >= b.height) {
    std::ostringstream out;
    out << "must be below height (" << b.height << "), got " << b.min_height;
    throw ConfigError(reader.PathOf("min_height"), out.str());
  }
}

}  // namespace

void BuildingSpec::SetFootprint(Footprint shape) {
  footprint = std::move(shape);
  const Bounds2 bounds = BoundsOf(footprint.outer);
  xmin = bounds.xmin;
  xmax = bounds.xmax;
  ymin = bounds.ymin;
  ymax = bounds.ymax;
}

const SettingsTable<BuildingSpec>& BuildingSettings() {
  static const SettingsTable<BuildingSpec> table{
      "building",
      "/buildings/<i>",
      "A building: an ns-3 Building, a box on the ground (x, y), or an exact footprint, a polygon "
      "with holes (footprint, holes); inside the venue and apart from the others.",
      {{"name", &BuildingSpec::name, NoRange(), "its name (\"building<i>\", counting from 0)"},
       {"x",
        CustomValue<BuildingSpec>{ReadX, XJson, "[min, max]"},
        NoRange(),
        "its x extent (a box; required without a footprint)",
        "m",
        {},
        nullptr,
        IsBox},
       {"y",
        CustomValue<BuildingSpec>{ReadY, YJson, "[min, max]"},
        NoRange(),
        "its y extent (a box; required without a footprint)",
        "m",
        {},
        nullptr,
        IsBox},
       {"footprint",
        CustomValue<BuildingSpec>{ReadFootprint, FootprintJson, "[[x, y], ...]"},
        NoRange(),
        "its exact ground shape instead of x and y: a simple polygon's vertices in order, the "
        "first not repeated",
        "m",
        {},
        nullptr,
        HasFootprint},
       {"holes",
        CustomValue<BuildingSpec>{ReadHoles, HolesJson, "[[[x, y], ...], ...]"},
        NoRange(),
        "the footprint's courtyards, each a polygon inside it",
        "m",
        {},
        nullptr,
        HasHoles},
       {"height", &BuildingSpec::height, Positive(), "its height", "m", {}, ""},
       {"min_height",
        &BuildingSpec::min_height,
        NonNegative(),
        "where a footprint building starts, below height (a part above a passage)",
        "m",
        {},
        nullptr,
        StartsAboveGround},
       {"floors", &BuildingSpec::floors, Integers(1, 200), "floors (ns-3's NFloors)"},
       {"rooms", CustomValue<BuildingSpec>{ReadRooms, RoomsJson, "[rooms_x, rooms_y]"}, NoRange(),
        "rooms per floor along x and y (ns-3's NRoomsX, NRoomsY)"},
       {"type",
        &BuildingSpec::type,
        NoRange(),
        "ns-3's Building::BuildingType",
        "",
        {"residential", "office", "commercial"}},
       {"walls",
        &BuildingSpec::walls,
        NoRange(),
        "ns-3's Building::ExtWallsType: the loss through its walls",
        "",
        {"wood", "concrete_with_windows", "concrete_without_windows", "stone_blocks"}}},
      CheckShape};
  return table;
}

}  // namespace rlpos
