// The observations that mean the same in every scenario: one layout whatever the venue, UE count
// or UAV count; the nearest UEs first; the buildings around the UAV; values inside their bounds.
#include "worker/env/gym/general_observation.h"

#include <gtest/gtest.h>

#include "common/config/config_error.h"
#include "common/scenario/scenario_parser.h"
#include "worker/env/gym/moves.h"

namespace rlpos {
namespace {

using nlohmann::json;

json Document(const std::string& file) {
  return ReadJsonFile(std::string(RLPOS_SOURCE_DIR) + "/campaigns/scenarios/" + file);
}

Scenario General(json document, int observed_ues = 16, int height_map = 9) {
  document["env"]["observations"] = {"zone", "ues", "heights", "others"};
  document["env"]["observed_ues"] = observed_ues;
  document["env"]["height_map"] = height_map;
  return ParseScenario(document);
}

// B's info with the UAV at `at`: UE i in LoS if los[i], all served by UAV 0.
StepInfo InfoOfB(const Scenario& s, const Vec3& at, std::vector<std::uint8_t> los) {
  StepInfo info;
  info.positions = {at};
  info.serving.assign(s.ues.size(), 0);
  info.los = std::move(los);
  info.snr_db.assign(s.ues.size(), 20.0);
  return info;
}

TEST(GeneralObservation, SameLayoutInEveryScenario) {
  const std::size_t expected = 3 + 16 * kUeSlotWidth + 9 * 9 + kOtherUavSlots * kOtherUavSlotWidth;
  for (const char* file : {"a.json", "b.json", "c.json", "campus2.json", "urban3.json"}) {
    const Scenario s = General(Document(file));
    EXPECT_EQ(ObservationBounds(s).Dim(), expected) << file;
  }
  // Plain fields keep their per-scenario layout (urban3: x, y, z of three UAVs, n_los, the SNR
  // of 20 UEs), and several UAVs their turn's one-hot.
  const Scenario plain = ParseScenario(Document("urban3.json"));
  EXPECT_EQ(ObservationBounds(plain).Dim(), 3 * 3 + 1 + 20 + 3);
}

TEST(GeneralObservation, NearestUesFirstThenEmptySlots) {
  const Scenario s = General(Document("b.json"), 6);
  // B's UEs: ue0 (85, 25), ue1 (70, 60), ue2 (30, 50), ue3 (5, 15). From (40, 50): ue2 (10 m),
  // ue1 (31.6 m), ue0 (51.5 m), ue3 (49.2 m): ue2, ue1, ue3, ue0.
  const StepInfo info = InfoOfB(s, {40, 50, 30}, {0, 1, 1, 0});
  const std::vector<double> obs = MakeObservation(s, info);
  ASSERT_EQ(obs.size(), ObservationBounds(s).Dim());
  const auto slot = [&](int k, int i) {
    return obs[3 + static_cast<std::size_t>(k * kUeSlotWidth + i)];
  };
  EXPECT_DOUBLE_EQ(slot(0, 1), -0.1);  // ue2: 10 m west
  EXPECT_DOUBLE_EQ(slot(0, 4), 1.0);   // in LoS
  EXPECT_DOUBLE_EQ(slot(1, 1), 0.3);   // ue1: 30 m east, 10 m north
  EXPECT_DOUBLE_EQ(slot(1, 2), 0.1);
  EXPECT_DOUBLE_EQ(slot(2, 1), -0.35);  // ue3
  EXPECT_DOUBLE_EQ(slot(2, 4), 0.0);
  EXPECT_DOUBLE_EQ(slot(3, 1), 0.45);  // ue0
  for (int k = 0; k < 4; ++k) {
    EXPECT_DOUBLE_EQ(slot(k, 0), 1.0) << "slot " << k;
    EXPECT_NEAR(slot(k, 3), -0.285, 1e-12);  // UEs 1.5 m up, the UAV at 30 m
    EXPECT_DOUBLE_EQ(slot(k, 5), 0.5);       // 20 dB within [-20, 60]
    EXPECT_DOUBLE_EQ(slot(k, 6), 1.0);       // served by the UAV
  }
  for (int k = 4; k < 6; ++k) {
    for (int i = 0; i < kUeSlotWidth; ++i)
      EXPECT_EQ(slot(k, i), 0.0) << "empty slot " << k;
  }
}

// Where a network that takes the UEs as a set (agent.ue_encoder) finds their slots: after the
// fields before "ues", whatever they are; the turn's one-hot comes after every field.
TEST(GeneralObservation, TheUeSlotsAreFoundAfterTheFieldsBeforeThem) {
  json document = Document("urban3.json");  // three UAVs, 20 UEs
  document["env"]["observations"] = {"x", "snr", "zone", "ues", "heights"};
  document["env"]["observed_ues"] = 5;
  const Scenario s = ParseScenario(document);
  const std::optional<SlotBlock> slots = UeSlotBlock(s);
  ASSERT_TRUE(slots);
  EXPECT_EQ(slots->offset, 3 + 20 + 3);
  EXPECT_EQ(slots->count, 5);
  EXPECT_EQ(slots->width, kUeSlotWidth);
  // Each slot's first value is its presence: 1 up to the UE count (B has 4), then 0.
  const Scenario b = General(Document("b.json"), 6);
  const std::vector<double> obs = MakeObservation(b, InfoOfB(b, {40, 50, 30}, {1, 1, 1, 1}));
  const std::optional<SlotBlock> b_slots = UeSlotBlock(b);
  ASSERT_TRUE(b_slots);
  for (int k = 0; k < b_slots->count; ++k)
    EXPECT_EQ(obs[static_cast<std::size_t>(b_slots->offset + k * b_slots->width)], k < 4 ? 1 : 0);
  EXPECT_FALSE(UeSlotBlock(ParseScenario(Document("b.json"))));
}

TEST(GeneralObservation, MoreUesThanSlotsShowsTheNearest) {
  const Scenario s = General(Document("b.json"), 2);
  const std::vector<double> obs = MakeObservation(s, InfoOfB(s, {80, 30, 30}, {1, 1, 1, 1}));
  EXPECT_DOUBLE_EQ(obs[3 + 1], 0.05);                 // ue0 (85, 25) first
  EXPECT_DOUBLE_EQ(obs[3 + kUeSlotWidth + 1], -0.1);  // then ue1 (70, 60)
}

TEST(GeneralObservation, TheHeightMapSeesTheBuildingsAroundTheUav) {
  const Scenario s = General(Document("b.json"), 16, 3);  // 3 x 3 cells of 5 m
  const std::size_t heights = 3 + 16 * kUeSlotWidth;
  // Over the tower's centre (45-55 x 45-55, 20 m): all nine cells (42.5-57.5) touch it.
  std::vector<double> obs = MakeObservation(s, InfoOfB(s, {50, 50, 30}, {0, 0, 0, 0}));
  for (std::size_t c = 0; c < 9; ++c)
    EXPECT_DOUBLE_EQ(obs[heights + c], 0.2) << "cell " << c;
  // At (60, 50): the west column (52.5-57.5) touches the tower; the others see open ground.
  obs = MakeObservation(s, InfoOfB(s, {60, 50, 30}, {0, 0, 0, 0}));
  for (std::size_t row = 0; row < 3; ++row) {
    EXPECT_DOUBLE_EQ(obs[heights + row * 3], 0.2) << "row " << row;
    EXPECT_DOUBLE_EQ(obs[heights + row * 3 + 1], 0.0);
    EXPECT_DOUBLE_EQ(obs[heights + row * 3 + 2], 0.0);
  }
}

TEST(GeneralObservation, ZoneAndOthersAreFromTheActiveUav) {
  const Scenario s = General(Document("urban3.json"));
  StepInfo info;
  for (const auto& uav : s.uavs)
    info.positions.push_back({uav.zone.xmin, uav.zone.ymax, uav.zone.zmin});
  info.positions[2] = {s.uavs[2].zone.xmax, s.uavs[2].zone.ymin, s.uavs[2].zone.zmax};
  info.serving.assign(s.ues.size(), 2);
  info.los.assign(s.ues.size(), 1);
  info.snr_db.assign(s.ues.size(), 100.0);  // clipped to 1
  info.active_uav = 2;
  const std::vector<double> obs = MakeObservation(s, info);
  const BoxSpace bounds = ObservationBounds(s);
  ASSERT_EQ(obs.size(), bounds.Dim());
  EXPECT_TRUE(bounds.Contains(obs));
  EXPECT_EQ(std::vector<double>(obs.begin(), obs.begin() + 3), (std::vector<double>{1, 0, 1}));
  EXPECT_DOUBLE_EQ(obs[3 + 5], 1.0);  // the SNR, clipped
  EXPECT_DOUBLE_EQ(obs[3 + 6], 1.0);  // served by the active UAV
  const std::size_t others = bounds.Dim() - kOtherUavSlots * kOtherUavSlotWidth;
  EXPECT_DOUBLE_EQ(obs[others], 1.0);
  EXPECT_DOUBLE_EQ(obs[others + kOtherUavSlotWidth], 1.0);
  EXPECT_DOUBLE_EQ(obs[others + 2 * kOtherUavSlotWidth], 0.0);  // only two others
  info.active_uav = 0;
  EXPECT_DOUBLE_EQ(MakeObservation(s, info)[3 + 6], 0.0);  // not served by UAV 0
}

TEST(GeneralObservation, SettingsAreCheckedAndWrittenWhereUsed) {
  json b = Document("b.json");
  b["env"]["height_map"] = 8;
  EXPECT_THROW(ParseScenario(b), ConfigError);
  b["env"]["height_map"] = 9;
  b["env"]["observed_ues"] = 65;
  EXPECT_THROW(ParseScenario(b), ConfigError);
  // A scenario without them keeps its document; one with them round-trips.
  EXPECT_FALSE(ToJson(ParseScenario(Document("b.json")))["env"].contains("observed_ues"));
  const Scenario general = General(Document("b.json"), 5, 7);
  const Scenario again = ParseScenario(ToJson(general));
  EXPECT_EQ(again.env.observed_ues, 5);
  EXPECT_EQ(again.env.height_map, 7);
  EXPECT_EQ(again.env.observations, general.env.observations);
}

// "to_best" flies towards the coverage map's pointer: without the map it is refused, by name.
TEST(GeneralObservation, ToBestNeedsTheCoverageMap) {
  json b = Document("b.json");
  b["env"]["actions"] = {"up", "down", "stay", "to_best"};
  try {
    ParseScenario(b);
    ADD_FAILURE() << "to_best without coverage was accepted";
  } catch (const ConfigError& e) {
    EXPECT_EQ(e.path(), "/env/actions");
    EXPECT_NE(std::string(e.what()).find("coverage"), std::string::npos) << e.what();
  }
  b["env"]["observations"] = {"zone", "coverage"};
  const Scenario s = ParseScenario(b);
  EXPECT_EQ(s.env.actions.back(), "to_best");
  EXPECT_EQ(ParseScenario(ToJson(s)).env.actions, s.env.actions);
}

}  // namespace
}  // namespace rlpos
