#include "common/job/position_rule.h"

#include <stdexcept>

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
    obstacles.push_back(BoxJson(b));
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
    rule.geometry.obstacles.push_back(BoxFromJson(b));
  return rule;
}

}  // namespace rlpos
