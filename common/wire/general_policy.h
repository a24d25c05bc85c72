#pragma once
// What a policy folder's result.json says of a policy for any scenario (rlpos-sim train
// --generated or --scenarios): "general", and the UAV counts it was trained for
// ("training": {"uavs": [min, max]}). Read by `position --policy` and by a campaign's check of a
// named policy alike.
#include <nlohmann/json.hpp>

namespace rlpos {

struct GeneralPolicyScope {
  bool general = false;
  int min_uavs = 1;
  int max_uavs = 1;
};

// Throws std::invalid_argument with "/general: ..." or "/training/uavs: ..." for a malformed
// field (a missing "general" is false).
GeneralPolicyScope ReadGeneralPolicyScope(const nlohmann::json& result);

}  // namespace rlpos
