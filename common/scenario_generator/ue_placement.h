#pragma once
// The UEs of a generated scenario: where they stand (in clusters or spread out, 1.5 m up, never
// in or against a building) and what they demand (an MCS-based mix).
#include <optional>
#include <string>
#include <vector>

#include "common/phy/mcs_table.h"
#include "common/scenario/scenario.h"
#include "common/scenario_generator/building_layouts.h"
#include "common/scenario_generator/portable_random.h"

namespace rlpos {

constexpr double kUeHeight = 1.5;
// The total demand per UAV is at most this many UEs at MCS 0 (unless every UE is at MCS 0).
constexpr int kDemandBudgetUes = 20;

struct UeDraw {
  std::vector<UeSpec> ues;
  std::string summary;  // one phrase for the scenario's description
};

// Draws `count` UEs for `uavs` UAVs; nullopt when this draw could not place them all.
std::optional<UeDraw> DrawUes(const Layout& layout, int count, int uavs, const PhyProfile& phy,
                              PortableRandom& random);

// The demand mix: MCS 0, 1, 2, 3 with weights 12, 5, 2, 1 (60, 25, 10, 5 %), then, while the
// total exceeds `budget_mbps`, the highest MCS (the last UE of it) steps down one, until the
// total fits or every UE is at MCS 0.
void DrawDemands(std::vector<UeSpec>& ues, double budget_mbps, const PhyProfile& phy,
                 PortableRandom& random);

}  // namespace rlpos
