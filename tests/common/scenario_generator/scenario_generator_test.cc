// rlpos-sim generate's engine over many seeds of every style and UAV count: every scenario
// parses and passes the checks, nothing stands inside a building, the baseline hides a UE where
// there are buildings, the same seed gives the same bytes, and the golden files pin one seed per
// style.
#include "common/scenario_generator/scenario_generator.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>
#include <iostream>
#include <map>
#include <set>
#include <sstream>

#include "common/config/config_error.h"
#include "common/phy/mcs_table.h"
#include "common/scenario/scenario_checks.h"
#include "common/scenario/scenario_parser.h"
#include "common/scenario_generator/hidden_ues.h"
#include "common/scenario_generator/uav_baseline.h"
#include "common/scenario_generator/ue_placement.h"

namespace rlpos {
namespace {

// Seeds per style and UAV count: 4 styles x 3 UAV counts x 84 = 1,008 scenarios.
constexpr std::uint64_t kSeedsPerCase = 84;

GeneratorOptions Options(std::uint64_t seed, GeneratorStyle style, int uavs) {
  GeneratorOptions o;
  o.seed = seed;
  o.style = style;
  o.uavs = uavs;
  return o;
}

// Everything the generator promises, checked on the document as a user would load it.
void ExpectValid(const GeneratedScenario& g) {
  const Scenario s = ParseScenario(ParseJsonText(g.json_text));  // throws if invalid
  const GeneratorStyle style = *g.options.style;
  ASSERT_EQ(s.uavs.size(), static_cast<std::size_t>(g.options.uavs));
  ASSERT_EQ(s.ues.size(), static_cast<std::size_t>(*g.options.ues));
  for (const auto& ue : s.ues) {
    EXPECT_EQ(BuildingContaining(s, ue.position), -1) << ue.name;
    EXPECT_EQ(ue.position.z, 1.5) << ue.name;
  }
  std::set<int> channels;
  for (const auto& uav : s.uavs) {
    EXPECT_EQ(BuildingContaining(s, uav.initial), -1) << uav.name;
    EXPECT_TRUE(uav.zone.Contains(uav.initial)) << uav.name;
    channels.insert(uav.channel);
  }
  EXPECT_EQ(channels.size(), s.uavs.size()) << "one channel per UAV";
  const int central = CentralBuilding(s.venue, s.buildings);
  if (style == GeneratorStyle::kOpen) {
    EXPECT_TRUE(s.buildings.empty());
    EXPECT_EQ(s.uavs[0].initial.z, 10.0);
  } else {
    ASSERT_GE(central, 0);
    const BuildingSpec& b = s.buildings[static_cast<std::size_t>(central)];
    for (const auto& uav : s.uavs) {
      EXPECT_EQ(uav.initial.z, b.height + 5.0) << "5 m above the central building";
      EXPECT_TRUE(uav.initial.x > b.xmin && uav.initial.x < b.xmax) << uav.name;
      EXPECT_TRUE(uav.initial.y > b.ymin && uav.initial.y < b.ymax) << uav.name;
    }
    EXPECT_GE(UesHiddenFromAll(s, s.InitialPlacement()), 1) << "the baseline sees every UE";
  }
  const PhyProfile phy{s.wifi.standard, s.wifi.width_mhz, s.wifi.guard_interval_ns,
                       s.wifi.spatial_streams};
  bool all_mcs0 = true;
  for (const auto& ue : s.ues)
    all_mcs0 = all_mcs0 && ue.demand_mcs == 0;
  EXPECT_TRUE(all_mcs0 || s.TotalDemandMbps() <=
                              kDemandBudgetUes * McsDataRateMbps(phy, 0) * g.options.uavs + 1e-9);
}

class EveryStyle : public ::testing::TestWithParam<GeneratorStyle> {};

TEST_P(EveryStyle, ManySeedsAreValidDeterministicAndDistinct) {
  const GeneratorStyle style = GetParam();
  std::set<std::string> texts;
  std::map<int, int> attempts;  // draws it took -> seeds
  int hidden = 0, scenarios = 0;
  for (int uavs = 1; uavs <= kMaxGeneratedUavs; ++uavs) {
    for (std::uint64_t seed = 0; seed < kSeedsPerCase; ++seed) {
      const GeneratedScenario g = GenerateScenario(Options(seed, style, uavs));
      SCOPED_TRACE(GenerateCommandLine(g.options));
      ExpectValid(g);
      EXPECT_EQ(GenerateScenario(Options(seed, style, uavs)).json_text, g.json_text);
      EXPECT_TRUE(texts.insert(g.json_text).second) << "two seeds gave one scenario";
      ++attempts[g.attempts];
      hidden += g.hidden_at_baseline;
      ++scenarios;
    }
  }
  std::ostringstream line;
  line << StyleName(style) << ": " << scenarios << " scenarios, draws per seed:";
  for (const auto& [draws, seeds] : attempts)
    line << " " << draws << "->" << seeds;
  line << "; UEs hidden at the baseline per scenario " << static_cast<double>(hidden) / scenarios;
  std::cout << line.str() << std::endl;
  RecordProperty("draws", line.str());
}

std::string StyleTestName(const ::testing::TestParamInfo<GeneratorStyle>& param) {
  return StyleName(param.param);
}

INSTANTIATE_TEST_SUITE_P(Generator, EveryStyle, ::testing::ValuesIn(AllGeneratorStyles()),
                         StyleTestName);

TEST(ScenarioGenerator, SeedSelectsTheStyleWhenNoneIsGiven) {
  GeneratorOptions o;
  for (std::uint64_t seed = 0; seed < 8; ++seed) {
    o.seed = seed;
    const GeneratedScenario g = GenerateScenario(o);
    EXPECT_EQ(*g.options.style, AllGeneratorStyles()[seed % 4]);
    EXPECT_EQ(g.json_text, GenerateScenario(Options(seed, *g.options.style, 1)).json_text);
  }
}

// Each UAV has a channel of its own: up to three on 160 MHz channels, four to six on 80 MHz ones
// (the 5 GHz band holds three 160 MHz channels), the scenario's Wi-Fi width with them.
TEST(ScenarioGenerator, EveryUavHasAChannelOfItsOwnUpToSix) {
  for (int uavs = 1; uavs <= kMaxGeneratedUavs; ++uavs) {
    const GeneratedScenario g = GenerateScenario(Options(7, GeneratorStyle::kCampus, uavs));
    SCOPED_TRACE(GenerateCommandLine(g.options));
    ASSERT_EQ(g.scenario.uavs.size(), static_cast<std::size_t>(uavs));
    EXPECT_EQ(g.scenario.wifi.width_mhz, uavs <= 3 ? 160 : 80);
    std::set<int> channels;
    for (const auto& uav : g.scenario.uavs)
      channels.insert(uav.channel == 0 ? g.scenario.wifi.channel : uav.channel);
    EXPECT_EQ(channels.size(), static_cast<std::size_t>(uavs));
    for (int channel : channels) {
      const auto& allowed = GeneratedUavChannels(uavs);
      EXPECT_NE(std::find(allowed.begin(), allowed.end(), channel), allowed.end()) << channel;
    }
  }
  EXPECT_EQ(kMaxGeneratedUavs, 6);
}

TEST(ScenarioGenerator, UeCountDefaultsAndOverrides) {
  GeneratorOptions o = Options(3, GeneratorStyle::kSuburb, 2);
  EXPECT_EQ(GenerateScenario(o).scenario.ues.size(), 12u);  // 8 + 4 per extra UAV
  o.ues = 1;
  EXPECT_EQ(GenerateScenario(o).scenario.ues.size(), 1u);
  o.ues = kMaxGeneratedUes;
  EXPECT_EQ(GenerateScenario(o).scenario.ues.size(), static_cast<std::size_t>(kMaxGeneratedUes));
}

TEST(ScenarioGenerator, OptionsOutOfRangeNameTheOption) {
  const auto path_of = [](const GeneratorOptions& o) {
    try {
      GenerateScenario(o);
    } catch (const ConfigError& e) {
      return e.path();
    }
    return std::string("no error");
  };
  GeneratorOptions o = Options(1, GeneratorStyle::kUrban, 0);
  EXPECT_EQ(path_of(o), "--uavs");
  o.uavs = kMaxGeneratedUavs + 1;
  EXPECT_EQ(path_of(o), "--uavs");
  o.uavs = 1;
  o.ues = 0;
  EXPECT_EQ(path_of(o), "--ues");
  o.ues = kMaxGeneratedUes + 1;
  EXPECT_EQ(path_of(o), "--ues");
  EXPECT_THROW(ParseStyle("downtown", "--style"), ConfigError);
}

TEST(ScenarioGenerator, RunningOutOfDrawsIsAnErrorNamingTheSeed) {
  // A seed whose first draw is rejected, with one draw allowed.
  for (std::uint64_t seed = 0; seed < 200; ++seed) {
    const GeneratorOptions o = Options(seed, GeneratorStyle::kSuburb, 1);
    if (GenerateScenario(o).attempts == 1)
      continue;
    try {
      GenerateScenario(o, 1);
      FAIL() << "no error for seed " << seed;
    } catch (const GeneratorError& e) {
      EXPECT_NE(std::string(e.what()).find("seed " + std::to_string(seed) + " (suburb"),
                std::string::npos)
          << e.what();
    }
    return;
  }
  FAIL() << "every suburb seed was kept at its first draw";
}

// The golden files: one seed per style, byte for byte. A change to the generator changes them;
// rewrite them with the command in the message if the change is meant.
struct Golden {
  const char* file;
  std::uint64_t seed;
  GeneratorStyle style;
  int uavs;
};

std::string GoldenTestName(const ::testing::TestParamInfo<Golden>& param) {
  return StyleName(param.param.style);
}

class GoldenFiles : public ::testing::TestWithParam<Golden> {};

TEST_P(GoldenFiles, BytesArePinned) {
  const Golden golden = GetParam();
  const std::string path =
      std::string(RLPOS_SOURCE_DIR) + "/tests/common/scenario_generator/golden/" + golden.file;
  std::ifstream in(path);
  ASSERT_TRUE(in) << "missing " << path;
  std::stringstream expected;
  expected << in.rdbuf();
  const GeneratedScenario g = GenerateScenario(Options(golden.seed, golden.style, golden.uavs));
  EXPECT_EQ(g.json_text, expected.str())
      << "the generator's output changed; if that is meant: build/bin/"
      << GenerateCommandLine(g.options) << " --out tests/common/scenario_generator/golden/"
      << golden.file;
}

INSTANTIATE_TEST_SUITE_P(
    Generator, GoldenFiles,
    ::testing::Values(Golden{"urban-s1-1uav.json", 1, GeneratorStyle::kUrban, 1},
                      Golden{"campus-s2-2uav.json", 2, GeneratorStyle::kCampus, 2},
                      Golden{"suburb-s3-1uav.json", 3, GeneratorStyle::kSuburb, 1},
                      Golden{"open-s4-3uav.json", 4, GeneratorStyle::kOpen, 3}),
    GoldenTestName);

}  // namespace
}  // namespace rlpos
