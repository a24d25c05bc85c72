#pragma once
// A UAV of the scenario ("uav", or each of "uavs"), declared once (uav_settings.cc) for the
// parser, ToJson and the docs.
#include <string>

#include "common/config/setting.h"
#include "common/scenario/geometry.h"

namespace rlpos {

// One UAV: an access point (or ad hoc peer) with the UEs' sink, on its own Wi-Fi channel.
struct UavSpec {
  std::string name = "uav";
  Vec3 initial{50.0, 50.0, 10.0};   // the venue's centre at 10 m (the parser's default)
  Box zone{0, 100, 0, 100, 1, 60};  // the venue, z in [1, its height] (likewise)
  int channel = 0;                  // 0: unset (UavSettings' doc says which it gets)
  double max_speed = 10.0;
  double max_climb = 3.0;
};

// The bound of uav.max_speed and uav.max_climb (m/s): faster than any multirotor flies.
constexpr double kMaxUavSpeed = 100.0;

const SettingsTable<UavSpec>& UavSettings();

}  // namespace rlpos
