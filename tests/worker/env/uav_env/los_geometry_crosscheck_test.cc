// The generator's LoS geometry (common/scenario_generator/los_geometry.h, no ns-3) against the
// LoS the analytic evaluator gets from ns-3's BuildingsChannelConditionModel: the same answer
// for every UE and every UAV position of a grid, on the shipped scenarios and on generated ones.
#include <gtest/gtest.h>

#include "common/scenario/scenario_checks.h"
#include "common/scenario_generator/los_geometry.h"
#include "common/scenario_generator/scenario_generator.h"
#include "worker/env/network/scenario_loading.h"
#include "worker/env/uav_env/analytic_evaluator.h"

namespace rlpos {
namespace {

struct Tally {
  int los = 0, nlos = 0;
};

// Compares the two over a 5 m grid of the zone of UAV 0 (every UAV's links depend on its own
// position only), positions inside buildings left out.
Tally ExpectSameLos(const Scenario& s) {
  AnalyticEvaluator evaluator(s);
  const Box& zone = s.uavs[0].zone;
  Tally tally;
  for (double z = zone.zmin; z <= zone.zmax; z += 10) {
    for (double x = zone.xmin; x <= zone.xmax; x += 5) {
      for (double y = zone.ymin; y <= zone.ymax; y += 5) {
        const Vec3 p{x, y, z};
        if (BuildingContaining(s, p) >= 0)
          continue;
        const auto links = evaluator.LinksAt(0, p);
        for (std::size_t i = 0; i < s.ues.size(); ++i) {
          const bool geometric = !LinkBlocked(s.buildings, s.ues[i].position, p);
          EXPECT_EQ(links[i].los, geometric) << s.name << ": UE " << s.ues[i].name << ", UAV at ("
                                             << x << ", " << y << ", " << z << ")";
          (geometric ? tally.los : tally.nlos) += 1;
        }
      }
    }
  }
  return tally;
}

class ShippedScenario : public ::testing::TestWithParam<std::string> {};

TEST_P(ShippedScenario, GeometryAgreesWithNs3) {
  const Scenario s =
      LoadScenario(std::string(RLPOS_SOURCE_DIR) + "/campaigns/scenarios/" + GetParam(), {});
  const Tally tally = ExpectSameLos(s);
  EXPECT_GT(tally.los, 0);
  if (!s.buildings.empty()) {
    EXPECT_GT(tally.nlos, 0);
  }
}

INSTANTIATE_TEST_SUITE_P(LosGeometry, ShippedScenario,
                         ::testing::Values("a.json", "b.json", "c.json", "campus2.json",
                                           "urban3.json"));

TEST(LosGeometry, GeneratedScenariosAgreeWithNs3) {
  for (GeneratorStyle style :
       {GeneratorStyle::kUrban, GeneratorStyle::kCampus, GeneratorStyle::kSuburb}) {
    GeneratorOptions options;
    options.seed = 11;
    options.style = style;
    const Tally tally = ExpectSameLos(GenerateScenario(options).scenario);
    EXPECT_GT(tally.los, 0);
    EXPECT_GT(tally.nlos, 0);
  }
}

}  // namespace
}  // namespace rlpos
