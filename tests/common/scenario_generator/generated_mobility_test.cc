// rlpos-sim generate --mobility: every UE moves by the model asked for, the same seed gives the
// same bytes, the rest of the scenario is what the seed gives without --mobility, and every UE
// can walk at any RngRun.
#include "common/scenario_generator/generated_mobility.h"

#include <gtest/gtest.h>

#include "common/config/config_error.h"
#include "common/mobility/ue_trajectories.h"
#include "common/scenario/scenario_parser.h"
#include "common/scenario_generator/scenario_generator.h"

namespace rlpos {
namespace {

GeneratorOptions Options(std::uint64_t seed, std::optional<MobilityModel> mobility) {
  GeneratorOptions o;
  o.seed = seed;
  o.mobility = mobility;
  return o;
}

class GeneratedMobility : public ::testing::TestWithParam<MobilityModel> {};

TEST_P(GeneratedMobility, SameSeedSameBytesAndTheSameScenarioOtherwise) {
  for (std::uint64_t seed = 0; seed < 8; ++seed) {  // two of each style
    const auto moving = GenerateScenario(Options(seed, GetParam()));
    EXPECT_EQ(GenerateScenario(Options(seed, GetParam())).json_text, moving.json_text);
    const std::string flag = " --mobility " + MobilityModelName(GetParam());
    EXPECT_NE(moving.scenario.description.find(flag), std::string::npos)
        << moving.scenario.description;
    for (const auto& ue : moving.scenario.ues)
      EXPECT_EQ(ue.mobility.model, GetParam()) << seed;
    // Without the UEs' mobility and the description, the document of the seed without it.
    auto with = nlohmann::json::parse(moving.json_text);
    auto without = nlohmann::json::parse(GenerateScenario(Options(seed, std::nullopt)).json_text);
    if (moving.attempts == 1) {
      for (auto& ue : with["ues"])
        ue.erase("mobility");
      with.erase("description");
      without.erase("description");
      EXPECT_EQ(with, without) << seed;
    }
    // Every UE walks at any RngRun.
    Scenario s = moving.scenario;
    for (std::uint64_t run = 1; run <= 5; ++run) {
      s.simulation.run = run;
      EXPECT_NO_THROW(UeTrajectories(s)) << s.name << " run " << run;
    }
  }
}

INSTANTIATE_TEST_SUITE_P(Generator, GeneratedMobility,
                         ::testing::ValuesIn(GeneratableMobilityModels()),
                         [](const ::testing::TestParamInfo<MobilityModel>& model) {
                           return MobilityModelName(model.param);
                         });

TEST(GeneratedMobility, AnUnknownModelNamesTheOption) {
  try {
    ParseGeneratedMobility("teleport", "--mobility");
    FAIL() << "expected a ConfigError";
  } catch (const ConfigError& e) {
    EXPECT_EQ(e.describe(),
              "--mobility: unknown mobility \"teleport\" (random_waypoint, gauss_markov or crowd)");
  }
}

}  // namespace
}  // namespace rlpos
