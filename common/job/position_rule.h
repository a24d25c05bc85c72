#pragma once
// How an eval job's position follows from the position its dependency (a train or position job)
// produced. Stored with the job so the store can bind the position without the scenario.
#include <nlohmann/json.hpp>

#include "common/job/offsets.h"

namespace rlpos {

struct PositionRule {
  int offset = 0;  // 0: the produced position as is; 1..5: the paper's position k around it
  double distance = kOffsetDistance;
  OffsetGeometry geometry;  // used when offset > 0
};

// The placement of the dependent eval. Offsets are defined around a single UAV: throws
// std::invalid_argument for an offset rule and a placement of several.
Placement ApplyPositionRule(const PositionRule& rule, const Placement& produced);

nlohmann::json ToJson(const PositionRule& rule);
// Throws std::invalid_argument on a malformed rule.
PositionRule PositionRuleFromJson(const nlohmann::json& json);

}  // namespace rlpos
