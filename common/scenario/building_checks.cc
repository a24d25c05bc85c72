#include "common/scenario/building_checks.h"

#include <algorithm>
#include <numeric>
#include <sstream>

#include "common/config/config_error.h"
#include "common/config/object_reader.h"
#include "common/scenario/building_obstacles.h"

namespace rlpos {
namespace {

void CheckShape(const BuildingSpec& b, const std::string& path) {
  if (!b.HasFootprint())
    return;
  if (const std::string defect = RingDefect(b.footprint.outer); !defect.empty())
    throw ConfigError(JoinPath(path, "footprint"), "not a simple polygon: " + defect);
  for (std::size_t k = 0; k < b.footprint.holes.size(); ++k) {
    if (const std::string defect = HoleDefect(b.footprint, k); !defect.empty())
      throw ConfigError(JoinPath(JoinPath(path, "holes"), k), defect);
  }
  if (!(Area(b.footprint) > 0))
    throw ConfigError(JoinPath(path, "holes"), "the holes leave no area");
}

void CheckInVenue(const BuildingSpec& b, const Venue& venue, const std::string& path) {
  const bool off_ground = b.xmin < 0 || b.xmax > venue.width || b.ymin < 0 || b.ymax > venue.depth;
  if (!off_ground && b.height <= venue.height)
    return;
  std::ostringstream out;
  out << "building \"" << b.name << "\" [" << b.xmin << ", " << b.xmax << "] x [" << b.ymin << ", "
      << b.ymax << "] x [" << b.min_height << ", " << b.height << "] is outside the venue";
  if (b.HasFootprint() && off_ground) {
    out << " (its footprint's bounds; clip it to [0, " << venue.width << "] x [0, " << venue.depth
        << "])";
    throw ConfigError(JoinPath(path, "footprint"), out.str());
  }
  throw ConfigError(path, out.str());
}

// For each building, the first earlier one it overlaps, or -1. A sweep along x: only buildings
// whose x ranges overlap are compared.
std::vector<int> FirstOverlapped(const std::vector<BuildingSpec>& buildings) {
  std::vector<std::size_t> order(buildings.size());
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    return buildings[a].xmin != buildings[b].xmin ? buildings[a].xmin < buildings[b].xmin : a < b;
  });
  std::vector<int> first(buildings.size(), -1);
  for (std::size_t s = 0; s < order.size(); ++s) {
    const BuildingSpec& left = buildings[order[s]];
    for (std::size_t t = s + 1; t < order.size() && buildings[order[t]].xmin < left.xmax; ++t) {
      const std::size_t i = std::max(order[s], order[t]), j = std::min(order[s], order[t]);
      if ((first[i] < 0 || static_cast<int>(j) < first[i]) &&
          BuildingsOverlap(buildings[i], buildings[j]))
        first[i] = static_cast<int>(j);
    }
  }
  return first;
}

}  // namespace

bool BuildingsOverlap(const BuildingSpec& a, const BuildingSpec& b) {
  if (!a.HasFootprint() && !b.HasFootprint())
    return a.xmin < b.xmax && b.xmin < a.xmax && a.ymin < b.ymax && b.ymin < a.ymax;
  const double tol = kBuildingOverlapTolerance;
  if (std::min(a.height, b.height) - std::max(a.min_height, b.min_height) <= tol)
    return false;  // one above the other
  return InteriorsOverlap(GroundShape(a), GroundShape(b), tol);
}

void CheckBuildings(const Scenario& s) {
  const std::vector<int> overlapped = FirstOverlapped(s.buildings);
  for (std::size_t i = 0; i < s.buildings.size(); ++i) {
    const BuildingSpec& b = s.buildings[i];
    const std::string path = JoinPath("/buildings", i);
    CheckShape(b, path);
    CheckInVenue(b, s.venue, path);
    if (const int j = overlapped[i]; j >= 0) {
      throw ConfigError(path, "building \"" + b.name + "\" overlaps building " + std::to_string(j) +
                                  " (\"" + s.buildings[j].name + "\")");
    }
  }
}

}  // namespace rlpos
