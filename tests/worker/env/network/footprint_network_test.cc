// Footprint buildings at the packet level: the exact shape blocks a link (its bounding box would
// block more), and ns-3's own building models, which know boxes only, are refused.
#include <gtest/gtest.h>

#include <string>

#include "common/config/config_error.h"
#include "tests/worker/env/network/shipped_scenario.h"
#include "worker/env/network/uav_network.h"

namespace rlpos {
namespace {

// Scenario B's UEs around one L-shaped building: arms x 40-60 (y 40-45) and y 40-60 (x 40-45).
const std::string kEll =
    "buildings=[{\"name\": \"ell\", \"footprint\": [[40, 40], [60, 40], [60, 45], [45, 45], [45, "
    "60], [40, 60]], \"height\": 20}]";

TEST(FootprintBuildings, TheExactShapeBlocksAtThePacketLevel) {
  const Scenario s = LoadShipped("b", {kEll});
  // In the L's notch: inside its bounding box, outside the building.
  UavNetwork network(s, {{55, 55, 8}});
  const auto links = network.Links();
  EXPECT_TRUE(links[1].los) << "ue1 (70, 60) sees the notch over open ground";
  EXPECT_FALSE(links[2].los) << "ue2 (30, 50) is behind the L's west arm";
  EXPECT_TRUE(links[0].los) << "ue0 (85, 25) passes south-east of the L";
}

TEST(FootprintBuildings, Ns3sBoxOnlyModelsAreRefused) {
  try {
    LoadShipped("b",
                {kEll, "propagation={\"type\": \"ns3::HybridBuildingsPropagationLossModel\"}"});
    FAIL() << "accepted";
  } catch (const ConfigError& e) {
    EXPECT_EQ(e.path().rfind("--set propagation=", 0), 0u) << e.path();  // blamed on the --set
    EXPECT_NE(std::string(e.what()).find("ns3::HybridBuildingsPropagationLossModel reads ns-3's "
                                         "buildings, which are boxes"),
              std::string::npos)
        << e.what();
  }
}

}  // namespace
}  // namespace rlpos
