#include "common/wire/general_policy.h"

#include <stdexcept>

namespace rlpos {

GeneralPolicyScope ReadGeneralPolicyScope(const nlohmann::json& result) {
  GeneralPolicyScope scope;
  const nlohmann::json general = result.value("general", nlohmann::json(false));
  if (!general.is_boolean())
    throw std::invalid_argument("/general: expected true or false");
  scope.general = general.get<bool>();
  if (!scope.general)
    return scope;
  const nlohmann::json training = result.value("training", nlohmann::json::object());
  const nlohmann::json uavs =
      training.is_object() ? training.value("uavs", nlohmann::json()) : nlohmann::json();
  if (!uavs.is_array() || uavs.size() != 2 || !uavs[0].is_number_integer() ||
      !uavs[1].is_number_integer() || uavs[0].get<int>() < 1 ||
      uavs[0].get<int>() > uavs[1].get<int>()) {
    throw std::invalid_argument("/training/uavs: expected [min, max] UAV counts");
  }
  scope.min_uavs = uavs[0].get<int>();
  scope.max_uavs = uavs[1].get<int>();
  return scope;
}

}  // namespace rlpos
