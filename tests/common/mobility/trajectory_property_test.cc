// Every mobility model over generated scenarios of every style and several RngRuns: the UEs
// never stand in a building or outside the venue (sampled finely in time and along each leg),
// walk no faster than their model allows, and the same run gives the same trajectories.
#include <gtest/gtest.h>

#include <cmath>
#include <map>

#include "common/config/config_error.h"
#include "common/mobility/ue_trajectories.h"
#include "common/scenario/scenario_checks.h"
#include "common/scenario/scenario_parser.h"
#include "common/scenario_generator/scenario_generator.h"

namespace rlpos {
namespace {

constexpr double kHorizon = 120.0;  // s
constexpr double kTimeStep = 0.1;   // s between samples in time
constexpr double kLegStep = 0.05;   // m between samples along a leg

MobilitySpec Model(MobilityModel model, const Scenario& s) {
  MobilitySpec m;
  m.model = model;
  m.random_waypoint.pause = 1.0;
  m.crowd.target = s.ues[0].position;  // on the ground, off every building
  m.crowd.start = 5.0;
  m.crowd.dwell = 20.0;
  return m;
}

// A generated scenario (seed, style) with every UE moving by `model`.
Scenario Moving(std::uint64_t seed, GeneratorStyle style, MobilityModel model) {
  GeneratorOptions o;
  o.seed = seed;
  o.style = style;
  Scenario s = GenerateScenario(o).scenario;
  for (auto& ue : s.ues)
    ue.mobility = Model(model, s);
  CheckScenarioGeometry(s);
  return s;
}

std::string Where(const Scenario& s, std::size_t ue, double t, const Vec3& p) {
  return s.name + " run " + std::to_string(s.simulation.run) + " UE " + std::to_string(ue) + " (" +
         MobilityModelName(s.ues[ue].mobility.model) + ") at t = " + std::to_string(t) + ": (" +
         std::to_string(p.x) + ", " + std::to_string(p.y) + ")";
}

bool OnWalkableGround(const Scenario& s, const Vec3& p) {
  return p.x >= 0 && p.x <= s.venue.width && p.y >= 0 && p.y <= s.venue.depth &&
         FootprintContaining(s, p.x, p.y) < 0;
}

// The highest speed each model may walk at.
double MaxSpeed(const MobilitySpec& m) {
  switch (m.model) {
    case MobilityModel::kRandomWalk:
      return m.random_walk.speed;
    case MobilityModel::kRandomWaypoint:
      return m.random_waypoint.speed_max;
    case MobilityModel::kGaussMarkov:
      return 2.0 * m.gauss_markov.speed;
    case MobilityModel::kCrowd:
      return m.crowd.speed;
    case MobilityModel::kStatic:
      break;
  }
  return 0.0;
}

void ExpectWalkable(const Scenario& s) {
  const auto trajectories = UeTrajectories(s, kHorizon);
  ASSERT_EQ(trajectories.size(), s.ues.size());
  for (std::size_t i = 0; i < trajectories.size(); ++i) {
    const auto& t = trajectories[i];
    EXPECT_TRUE(t.Moves()) << Where(s, i, 0, s.ues[i].position);
    // Every model but the crowd walks until the horizon; a dispersed crowd stays put.
    if (s.ues[i].mobility.model != MobilityModel::kCrowd) {
      EXPECT_GE(t.waypoints().back().time, kHorizon) << s.name << " UE " << i;
    }
    for (double time = 0; time <= kHorizon; time += kTimeStep) {
      const Vec3 p = t.PositionAt(time);
      ASSERT_TRUE(OnWalkableGround(s, p)) << Where(s, i, time, p);
      ASSERT_DOUBLE_EQ(p.z, s.ues[i].position.z);
    }
    const auto& w = t.waypoints();
    for (std::size_t k = 1; k < w.size(); ++k) {
      const Vec3 &a = w[k - 1].position, &b = w[k].position;
      const double length = std::hypot(b.x - a.x, b.y - a.y);
      const double duration = w[k].time - w[k - 1].time;
      if (length > 0) {
        ASSERT_GT(duration, 0) << Where(s, i, w[k].time, b);
        // Times are rounded to the nanosecond: a hair over the speed is that rounding.
        ASSERT_LE(length / duration, MaxSpeed(s.ues[i].mobility) * (1 + 1e-6))
            << Where(s, i, w[k].time, b);
      }
      const int n = static_cast<int>(std::ceil(length / kLegStep));
      for (int j = 0; j <= n; ++j) {
        const double f = n == 0 ? 0.0 : static_cast<double>(j) / n;
        const Vec3 p{a.x + (b.x - a.x) * f, a.y + (b.y - a.y) * f, a.z};
        ASSERT_TRUE(OnWalkableGround(s, p)) << Where(s, i, w[k - 1].time, p) << " on a leg";
      }
    }
  }
}

class EveryModel : public ::testing::TestWithParam<MobilityModel> {};

TEST_P(EveryModel, KeepsUesInTheVenueAndOutOfBuildings) {
  // 3 seeds x 4 styles x 3 RngRuns = 36 scenarios of about 10 UEs each, per model.
  for (std::uint64_t seed = 0; seed < 3; ++seed) {
    for (GeneratorStyle style : AllGeneratorStyles()) {
      Scenario s = Moving(seed, style, GetParam());
      for (std::uint64_t run = 1; run <= 3; ++run) {
        s.simulation.run = run;
        ExpectWalkable(s);
        if (HasFatalFailure())
          return;
      }
    }
  }
}

TEST_P(EveryModel, SameRunSameTrajectoriesAnotherRunAnother) {
  Scenario s = Moving(1, GeneratorStyle::kUrban, GetParam());
  const auto first = UeTrajectories(s, kHorizon);
  const auto again = UeTrajectories(s, kHorizon);
  s.simulation.run = 2;
  const auto other = UeTrajectories(s, kHorizon);
  for (std::size_t i = 0; i < first.size(); ++i) {
    const auto& a = first[i].waypoints();
    const auto& b = again[i].waypoints();
    ASSERT_EQ(a.size(), b.size());
    for (std::size_t k = 0; k < a.size(); ++k) {
      EXPECT_EQ(a[k].time, b[k].time);
      EXPECT_EQ(a[k].position.x, b[k].position.x);
      EXPECT_EQ(a[k].position.y, b[k].position.y);
    }
    // Another RngRun, and another UE of the same run, walk elsewhere.
    EXPECT_NE(first[i].PositionAt(60).x, other[i].PositionAt(60).x) << "UE " << i;
    if (i > 0) {
      const double moved = first[i].PositionAt(60).x - s.ues[i].position.x;
      const double moved_before = first[i - 1].PositionAt(60).x - s.ues[i - 1].position.x;
      EXPECT_NE(moved, moved_before) << "UE " << i;
    }
  }
}

INSTANTIATE_TEST_SUITE_P(Mobility, EveryModel,
                         ::testing::Values(MobilityModel::kRandomWalk,
                                           MobilityModel::kRandomWaypoint,
                                           MobilityModel::kGaussMarkov, MobilityModel::kCrowd),
                         [](const ::testing::TestParamInfo<MobilityModel>& model) {
                           return MobilityModelName(model.param);
                         });

TEST(Mobility, StaticUesStayPut) {
  Scenario s = Moving(0, GeneratorStyle::kCampus, MobilityModel::kStatic);
  const auto trajectories = UeTrajectories(s, kHorizon);
  for (std::size_t i = 0; i < s.ues.size(); ++i) {
    ASSERT_EQ(trajectories[i].waypoints().size(), 1u);
    EXPECT_EQ(trajectories[i].PositionAt(50).x, s.ues[i].position.x);
  }
  EXPECT_FALSE(AnyUeMoves(s));
}

TEST(Mobility, ACrowdGathersAroundItsTarget) {
  Scenario s = Moving(2, GeneratorStyle::kUrban, MobilityModel::kCrowd);
  for (auto& ue : s.ues) {
    ue.mobility.crowd.speed = 5.0;
    ue.mobility.crowd.start = 0.0;
    ue.mobility.crowd.dwell = 1000.0;  // still there at the end
  }
  const auto trajectories = UeTrajectories(s, kHorizon);
  const Vec3& target = s.ues[0].mobility.crowd.target;
  for (std::size_t i = 0; i < s.ues.size(); ++i) {
    const Vec3 p = trajectories[i].PositionAt(kHorizon);
    EXPECT_LE(std::hypot(p.x - target.x, p.y - target.y), s.ues[i].mobility.crowd.radius + 1e-9)
        << Where(s, i, kHorizon, p);
  }
}

TEST(Mobility, NoWayRoundTheBuildingsIsAnErrorNamingTheUe) {
  // A courtyard [10, 20] x [10, 20] walled in by four buildings; the crowd gathers outside.
  const auto doc = nlohmann::json::parse(R"({
    "venue": {"width": 40, "depth": 30},
    "buildings": [{"x": [0, 30], "y": [0, 10], "height": 10},
                  {"x": [0, 30], "y": [20, 30], "height": 10},
                  {"x": [0, 10], "y": [10, 20], "height": 10},
                  {"x": [20, 30], "y": [10, 20], "height": 10}],
    "uav": {"position": [35, 15, 20]},
    "ues": [{"name": "walker", "position": [35, 5, 1.5], "demand": {"mbps": 1}},
            {"name": "shut-in", "position": [15, 15, 1.5], "demand": {"mbps": 1},
             "mobility": {"model": "crowd", "target": [35, 25], "radius": 2}}]})");
  const Scenario s = ParseScenario(doc);
  try {
    UeTrajectories(s);
    FAIL() << "expected a ConfigError";
  } catch (const ConfigError& e) {
    EXPECT_EQ(e.describe(),
              "/ues/1/mobility: UE \"shut-in\" (crowd): no way round the buildings to a spot "
              "within 2 m of the crowd's target");
  }
}

}  // namespace
}  // namespace rlpos
