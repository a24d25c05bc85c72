#include "common/scenario_generator/ue_placement.h"

#include <algorithm>

namespace rlpos {
namespace {

// A UE keeps this far (m) from every wall and from the venue's edges.
constexpr double kClearance = 1.0;
constexpr int kTriesPerUe = 200;

bool Standable(const Layout& layout, double x, double y) {
  if (x < kClearance || y < kClearance || x > layout.venue.width - kClearance ||
      y > layout.venue.depth - kClearance) {
    return false;
  }
  for (const auto& b : layout.buildings) {
    if (x > b.xmin - kClearance && x < b.xmax + kClearance && y > b.ymin - kClearance &&
        y < b.ymax + kClearance) {
      return false;
    }
  }
  return true;
}

bool Taken(const std::vector<UeSpec>& ues, double x, double y) {
  for (const auto& ue : ues) {
    if (ue.position.x == x && ue.position.y == y)
      return true;
  }
  return false;
}

// A free spot uniform over the venue; nullopt after kTriesPerUe tries.
std::optional<Vec3> DrawSpreadSpot(const Layout& layout, const std::vector<UeSpec>& ues,
                                   PortableRandom& random) {
  for (int tries = 0; tries < kTriesPerUe; ++tries) {
    const double x = random.UniformHalfMetres(0, layout.venue.width);
    const double y = random.UniformHalfMetres(0, layout.venue.depth);
    if (Standable(layout, x, y) && !Taken(ues, x, y))
      return Vec3{x, y, kUeHeight};
  }
  return std::nullopt;
}

// A free spot in the square of half side `radius` around `centre`.
std::optional<Vec3> DrawClusterSpot(const Layout& layout, const std::vector<UeSpec>& ues,
                                    const Vec3& centre, double radius, PortableRandom& random) {
  for (int tries = 0; tries < kTriesPerUe; ++tries) {
    const double x = centre.x + random.UniformHalfMetres(-radius, radius);
    const double y = centre.y + random.UniformHalfMetres(-radius, radius);
    if (Standable(layout, x, y) && !Taken(ues, x, y))
      return Vec3{x, y, kUeHeight};
  }
  return std::nullopt;
}

// Clustered UEs: 1-3 clusters (k to k + 1 with k UAVs), each centred on a free spot, of half
// side 8-15 m; UEs go to the clusters in turn.
std::optional<std::string> PlaceClusters(const Layout& layout, int count, int uavs,
                                         std::vector<UeSpec>& ues, PortableRandom& random) {
  const long long clusters =
      uavs == 1 ? random.UniformInt(1, 3) : random.UniformInt(uavs, uavs + 1);
  std::vector<Vec3> centres;
  std::vector<double> radii;
  for (long long k = 0; k < clusters; ++k) {
    const auto centre = DrawSpreadSpot(layout, {}, random);
    if (!centre)
      return std::nullopt;
    centres.push_back(*centre);
    radii.push_back(static_cast<double>(random.UniformInt(8, 15)));
  }
  for (int i = 0; i < count; ++i) {
    const std::size_t k = static_cast<std::size_t>(i) % centres.size();
    const auto spot = DrawClusterSpot(layout, ues, centres[k], radii[k], random);
    if (!spot)
      return std::nullopt;
    ues.push_back({});
    ues.back().position = *spot;
  }
  return "in " + std::to_string(clusters) + (clusters == 1 ? " cluster" : " clusters");
}

std::optional<std::string> PlaceSpread(const Layout& layout, int count, std::vector<UeSpec>& ues,
                                       PortableRandom& random) {
  for (int i = 0; i < count; ++i) {
    const auto spot = DrawSpreadSpot(layout, ues, random);
    if (!spot)
      return std::nullopt;
    ues.push_back({});
    ues.back().position = *spot;
  }
  return std::string("spread out");
}

}  // namespace

void DrawDemands(std::vector<UeSpec>& ues, double budget_mbps, const PhyProfile& phy,
                 PortableRandom& random) {
  const std::vector<int> weights{12, 5, 2, 1};
  double total = 0;
  for (auto& ue : ues) {
    ue.demand_mcs = static_cast<int>(random.Weighted(weights));
    ue.demand_mbps = McsDataRateMbps(phy, ue.demand_mcs);
    total += ue.demand_mbps;
  }
  while (total > budget_mbps) {
    auto highest = ues.rbegin();
    for (auto it = ues.rbegin(); it != ues.rend(); ++it) {
      if (it->demand_mcs > highest->demand_mcs)
        highest = it;
    }
    if (highest->demand_mcs == 0)
      break;
    total -= highest->demand_mbps;
    highest->demand_mcs -= 1;
    highest->demand_mbps = McsDataRateMbps(phy, highest->demand_mcs);
    total += highest->demand_mbps;
  }
}

std::optional<UeDraw> DrawUes(const Layout& layout, int count, int uavs, const PhyProfile& phy,
                              PortableRandom& random) {
  UeDraw draw;
  const bool clustered = random.Chance(1, 2);
  const auto placed = clustered ? PlaceClusters(layout, count, uavs, draw.ues, random)
                                : PlaceSpread(layout, count, draw.ues, random);
  if (!placed)
    return std::nullopt;
  for (std::size_t i = 0; i < draw.ues.size(); ++i)
    draw.ues[i].name = "ue" + std::to_string(i);
  // Twenty UEs at MCS 0 per UAV: scenario A's total demand (1,170 Mbit/s at 160 MHz), the
  // largest of the shipped scenarios, per UAV.
  DrawDemands(draw.ues, kDemandBudgetUes * McsDataRateMbps(phy, 0) * uavs, phy, random);
  int mcs_counts[4] = {0, 0, 0, 0};
  for (const auto& ue : draw.ues)
    ++mcs_counts[std::min(ue.demand_mcs, 3)];
  draw.summary = std::to_string(count) + " UEs " + *placed +
                 " (MCS 0/1/2/3: " + std::to_string(mcs_counts[0]) + "/" +
                 std::to_string(mcs_counts[1]) + "/" + std::to_string(mcs_counts[2]) + "/" +
                 std::to_string(mcs_counts[3]) + ")";
  return draw;
}

}  // namespace rlpos
