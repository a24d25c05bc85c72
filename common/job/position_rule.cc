#include "common/job/position_rule.h"

#include <stdexcept>
#include <utility>

#include "common/config/config_error.h"
#include "common/scenario/geometry.h"

namespace rlpos {
namespace {

using nlohmann::json;

json BoxJson(const Box& b) {
  return {b.xmin, b.xmax, b.ymin, b.ymax, b.zmin, b.zmax};
}

Box BoxFromJson(const json& v) {
  if (!v.is_array() || v.size() != 6)
    throw std::invalid_argument("a box needs 6 numbers");
  for (const auto& x : v) {
    if (!x.is_number())
      throw std::invalid_argument("a box needs 6 numbers");
  }
  return {v[0].get<double>(), v[1].get<double>(), v[2].get<double>(),
          v[3].get<double>(), v[4].get<double>(), v[5].get<double>()};
}

Ring RingFromJson(const json& v) {
  try {
    return ReadRing(v, "/footprint");
  } catch (const ConfigError& e) {
    throw std::invalid_argument(std::string("an obstacle's ring: ") + e.what());
  }
}

// A box keeps its six numbers (the form rules had before footprints, which campaign ids hash);
// a footprint building is {"footprint", "holes", "z": [zmin, zmax]}.
json SolidJson(const Solid& solid) {
  if (solid.IsBox())
    return BoxJson(solid.box);
  json holes = json::array();
  for (const Ring& hole : solid.footprint.holes)
    holes.push_back(RingJson(hole));
  return {{"footprint", RingJson(solid.footprint.outer)},
          {"holes", holes},
          {"z", {solid.box.zmin, solid.box.zmax}}};
}

Solid SolidFromJson(const json& v) {
  if (v.is_array())
    return Solid::OfBox(BoxFromJson(v));
  if (!v.is_object() || !v.contains("footprint") || !v.contains("holes") ||
      !v["holes"].is_array() || !v.contains("z") || !v["z"].is_array() || v["z"].size() != 2 ||
      !v["z"][0].is_number() || !v["z"][1].is_number()) {
    throw std::invalid_argument("an obstacle is a box or {footprint, holes, z}");
  }
  Footprint footprint{RingFromJson(v["footprint"]), {}};
  for (const auto& hole : v["holes"])
    footprint.holes.push_back(RingFromJson(hole));
  const double zmin = v["z"][0].get<double>(), zmax = v["z"][1].get<double>();
  if (!(zmin < zmax) || !FootprintDefect(footprint).empty())
    throw std::invalid_argument("an obstacle's footprint is not a valid polygon");
  return Solid::Prism(std::move(footprint), zmin, zmax);
}

}  // namespace

Placement ApplyPositionRule(const PositionRule& rule, const Placement& produced) {
  if (rule.offset == 0)
    return produced;
  if (produced.size() != 1) {
    throw std::invalid_argument("offset position " + std::to_string(rule.offset) +
                                " is defined around one UAV, the placement has " +
                                std::to_string(produced.size()));
  }
  return {OffsetPosition(produced.front(), rule.offset, rule.geometry, rule.distance)};
}

json ToJson(const PositionRule& rule) {
  if (rule.offset == 0)
    return {{"offset", 0}};
  json obstacles = json::array();
  for (const auto& b : rule.geometry.obstacles)
    obstacles.push_back(SolidJson(b));
  return {{"offset", rule.offset},
          {"distance", rule.distance},
          {"bounds", BoxJson(rule.geometry.bounds)},
          {"obstacles", obstacles}};
}

PositionRule PositionRuleFromJson(const json& v) {
  if (!v.is_object() || !v.contains("offset") || !v["offset"].is_number_integer()) {
    throw std::invalid_argument("a position rule needs an integer \"offset\"");
  }
  PositionRule rule;
  rule.offset = v["offset"].get<int>();
  if (rule.offset < 0 || rule.offset > kOffsetCount) {
    throw std::invalid_argument("position rule offset " + std::to_string(rule.offset) +
                                " is not in 0..5");
  }
  if (rule.offset == 0)
    return rule;
  if (!v.contains("distance") || !v["distance"].is_number() || !v.contains("bounds") ||
      !v.contains("obstacles") || !v["obstacles"].is_array()) {
    throw std::invalid_argument("an offset rule needs distance, bounds and obstacles");
  }
  rule.distance = v["distance"].get<double>();
  rule.geometry.bounds = BoxFromJson(v["bounds"]);
  for (const auto& b : v["obstacles"])
    rule.geometry.obstacles.push_back(SolidFromJson(b));
  return rule;
}

}  // namespace rlpos
