#pragma once
// The UAV baseline of a generated scenario, by the paper's convention: 5 m above the central
// building (the one nearest the venue's centre), or the venue's centre 10 m up in free space.
// K UAVs share that spot, spread along the building's longer side (5 m apart in free space),
// each on its own 160 MHz channel, each free to fly the whole venue from 5 m up.
#include <string>
#include <vector>

#include "common/scenario/scenario.h"

namespace rlpos {

// The Wi-Fi channel width of a generated scenario with `uavs` UAVs: 160 MHz while the 5 GHz band
// holds a channel that wide for each (three), 80 MHz for four to six.
int GeneratedChannelWidthMhz(int uavs);
// The channels of the generated UAVs of a scenario with `uavs` UAVs, in order: distinct channels
// of GeneratedChannelWidthMhz(uavs).
const std::vector<int>& GeneratedUavChannels(int uavs);

// Index of the building nearest the venue's centre (distance from the centre to its footprint,
// then to the footprint's centre, then the lower index), or -1 without buildings.
int CentralBuilding(const Venue& venue, const std::vector<BuildingSpec>& buildings);

// The baseline UAVs: named "uav" alone, else uav1..uavK with explicit channels.
std::vector<UavSpec> BaselineUavs(const Venue& venue, const std::vector<BuildingSpec>& buildings,
                                  int count);

// One phrase for the description: where the baseline is.
std::string BaselineSummary(const Venue& venue, const std::vector<BuildingSpec>& buildings);

}  // namespace rlpos
