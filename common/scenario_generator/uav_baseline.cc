#include "common/scenario_generator/uav_baseline.h"

#include <algorithm>
#include <cmath>

namespace rlpos {
namespace {

constexpr double kAboveRoof = 5.0;
constexpr double kOpenHeight = 10.0;
constexpr double kZoneFloor = 5.0;

double Squared(double v) {
  return v * v;
}

// Squared distance from (x, y) to the footprint (0 inside).
double SquaredDistanceToFootprint(const BuildingSpec& b, double x, double y) {
  const double dx = std::max({b.xmin - x, 0.0, x - b.xmax});
  const double dy = std::max({b.ymin - y, 0.0, y - b.ymax});
  return Squared(dx) + Squared(dy);
}

// Rounds to the half-metre grid the rest of the scenario is on (exact, portable).
double HalfMetre(double v) {
  return std::floor(v * 2.0 + 0.5) / 2.0;
}

}  // namespace

int GeneratedChannelWidthMhz(int uavs) {
  return uavs <= 3 ? 160 : 80;
}

const std::vector<int>& GeneratedUavChannels(int uavs) {
  static const std::vector<int> wide{50, 114, 163};
  static const std::vector<int> narrow{42, 58, 106, 122, 138, 155};
  return GeneratedChannelWidthMhz(uavs) == 160 ? wide : narrow;
}

int CentralBuilding(const Venue& venue, const std::vector<BuildingSpec>& buildings) {
  const double cx = venue.width / 2, cy = venue.depth / 2;
  int best = -1;
  double best_edge = 0, best_centre = 0;
  for (std::size_t i = 0; i < buildings.size(); ++i) {
    const BuildingSpec& b = buildings[i];
    const double edge = SquaredDistanceToFootprint(b, cx, cy);
    const double centre = Squared((b.xmin + b.xmax) / 2 - cx) + Squared((b.ymin + b.ymax) / 2 - cy);
    if (best < 0 || edge < best_edge || (edge == best_edge && centre < best_centre)) {
      best = static_cast<int>(i);
      best_edge = edge;
      best_centre = centre;
    }
  }
  return best;
}

std::vector<UavSpec> BaselineUavs(const Venue& venue, const std::vector<BuildingSpec>& buildings,
                                  int count) {
  const int central = CentralBuilding(venue, buildings);
  std::vector<UavSpec> uavs;
  for (int i = 0; i < count; ++i) {
    UavSpec uav;
    uav.name = count == 1 ? "uav" : "uav" + std::to_string(i + 1);
    uav.channel = count == 1 ? 0 : GeneratedUavChannels(count)[static_cast<std::size_t>(i)];
    uav.zone = {0, venue.width, 0, venue.depth, kZoneFloor, venue.height};
    if (central < 0) {
      const double offset = 5.0 * (i - (count - 1) / 2.0);
      uav.initial = {HalfMetre(venue.width / 2 + offset), venue.depth / 2, kOpenHeight};
    } else {
      // Evenly along the roof's longer side: the (i + 1)-th of count + 1 equal steps.
      const BuildingSpec& b = buildings[static_cast<std::size_t>(central)];
      const double along = (i + 1.0) / (count + 1.0);
      const bool wide = b.xmax - b.xmin >= b.ymax - b.ymin;
      const double x = wide ? b.xmin + along * (b.xmax - b.xmin) : (b.xmin + b.xmax) / 2;
      const double y = wide ? (b.ymin + b.ymax) / 2 : b.ymin + along * (b.ymax - b.ymin);
      uav.initial = {HalfMetre(x), HalfMetre(y), b.height + kAboveRoof};
    }
    uavs.push_back(uav);
  }
  return uavs;
}

std::string BaselineSummary(const Venue& venue, const std::vector<BuildingSpec>& buildings) {
  const int central = CentralBuilding(venue, buildings);
  if (central < 0)
    return "the venue's centre, 10 m up";
  return "5 m above " + buildings[static_cast<std::size_t>(central)].name +
         ", the building nearest the centre";
}

}  // namespace rlpos
