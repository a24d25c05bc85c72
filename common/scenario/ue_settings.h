#pragma once
// A UE of the scenario (each of "ues"), declared once (ue_settings.cc) for the parser, ToJson and
// the docs. Its "mobility" has its own tables (mobility_settings.h).
#include <string>

#include "common/config/setting.h"
#include "common/scenario/geometry.h"
#include "common/scenario/mobility_settings.h"

namespace rlpos {

struct UeSpec {
  std::string name;
  Vec3 position;
  std::string uav;           // empty: unset (UeSettings' doc says which serves it)
  double demand_mbps = 0.0;  // resolved from "mbps" or "mcs" (the parser, with the PHY)
  int demand_mcs = -1;       // the MCS the demand was given as, or -1 when given in Mbit/s
  MobilitySpec mobility;
};

const SettingsTable<UeSpec>& UeSettings();

}  // namespace rlpos
