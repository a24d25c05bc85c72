#pragma once
// The scenario's "venue": the ground everything stands on, declared once (venue_settings.cc).
#include "common/config/setting.h"

namespace rlpos {

struct Venue {
  double width = 100.0;
  double depth = 100.0;
  double height = 60.0;
};

const SettingsTable<Venue>& VenueSettings();

}  // namespace rlpos
