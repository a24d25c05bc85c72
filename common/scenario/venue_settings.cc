#include "common/scenario/venue_settings.h"

namespace rlpos {

const SettingsTable<Venue>& VenueSettings() {
  static const SettingsTable<Venue> table{
      "venue",
      "/venue",
      "The ground, [0, width] x [0, depth], and the height nothing in it exceeds.",
      {{"width", &Venue::width, Positive(), "x extent", "m"},
       {"depth", &Venue::depth, Positive(), "y extent", "m"},
       {"height", &Venue::height, Positive(), "height limit of anything in the venue", "m"}}};
  return table;
}

}  // namespace rlpos
