// The one LoS rule (common/geometry/obstacles.h), directly and as the packet level's
// ns3::ObstaclesChannelConditionModel, against ns-3's BuildingsChannelConditionModel for the same
// two points, over the cases the env's trajectories rarely meet: both ends indoors (one building
// or two), one indoors, and points on the boxes' faces, edges and corners.
#include <gtest/gtest.h>
#include <ns3/building.h>
#include <ns3/buildings-channel-condition-model.h>
#include <ns3/constant-position-mobility-model.h>
#include <ns3/mobility-building-info.h>
#include <ns3/simulator.h>

#include <memory>
#include <random>
#include <vector>

#include "common/geometry/obstacles.h"
#include "common/scenario/building_obstacles.h"
#include "worker/env/network/obstacles_channel_condition_model.h"

namespace rlpos {
namespace {

BuildingSpec Building(double xmin, double xmax, double ymin, double ymax, double height) {
  BuildingSpec b;
  b.xmin = xmin;
  b.xmax = xmax;
  b.ymin = ymin;
  b.ymax = ymax;
  b.height = height;
  return b;
}

ns3::Ptr<ns3::MobilityModel> End() {
  auto mobility = ns3::CreateObject<ns3::ConstantPositionMobilityModel>();
  mobility->AggregateObject(ns3::CreateObject<ns3::MobilityBuildingInfo>());
  return mobility;
}

TEST(Obstacles, SameLosAsNs3) {
  const std::vector<BuildingSpec> buildings = {
      Building(10, 30, 10, 25, 20), Building(40, 45.5, 10, 60, 35), Building(10, 30, 40, 50, 8)};
  ns3::Simulator::Destroy();  // ns-3's building list is process-wide: start from an empty one
  for (const auto& b : buildings) {
    auto building = ns3::CreateObject<ns3::Building>();
    building->SetBoundaries(ns3::Box(b.xmin, b.xmax, b.ymin, b.ymax, 0.0, b.height));
  }
  const auto ours = std::make_shared<const Obstacles>(BuildingObstacles(buildings));
  auto channel_model = ns3::CreateObject<ns3::ObstaclesChannelConditionModel>();
  channel_model->SetObstacles(ours);
  auto ns3_rule = ns3::CreateObject<ns3::BuildingsChannelConditionModel>();
  auto a = End(), b = End();
  // Points on a 2.5 m grid (it holds every face of the boxes) and anywhere.
  std::mt19937 rng(5);
  std::uniform_int_distribution<int> grid(0, 28);
  std::uniform_real_distribution<double> any(0, 70);
  const auto point = [&](bool on_grid) {
    return on_grid ? Vec3{2.5 * grid(rng), 2.5 * grid(rng), 2.5 * (grid(rng) % 17)}
                   : Vec3{any(rng), any(rng), any(rng) / 2};
  };
  int los = 0, nlos = 0, both_in = 0, one_in = 0;
  for (int k = 0; k < 200000; ++k) {
    const Vec3 p = point(k % 2 == 0), q = point(k % 3 == 0);
    a->SetPosition({p.x, p.y, p.z});
    b->SetPosition({q.x, q.y, q.z});
    const auto condition = ns3_rule->GetChannelCondition(a, b);
    const auto ours_in_ns3 = channel_model->GetChannelCondition(a, b);
    const bool theirs = condition->IsLos();
    ASSERT_EQ(ours_in_ns3->IsLos(), theirs);
    ASSERT_EQ(ours_in_ns3->GetO2iCondition(), condition->GetO2iCondition());
    ASSERT_EQ(ours->Los(p, q), theirs) << "(" << p.x << ", " << p.y << ", " << p.z << ") to ("
                                       << q.x << ", " << q.y << ", " << q.z << ")";
    (theirs ? los : nlos) += 1;
    const int inside = (ours->SolidAt(p) >= 0 ? 1 : 0) + (ours->SolidAt(q) >= 0 ? 1 : 0);
    both_in += inside == 2 ? 1 : 0;
    one_in += inside == 1 ? 1 : 0;
  }
  EXPECT_GT(los, 0);
  EXPECT_GT(nlos, 0);
  EXPECT_GT(both_in, 0);
  EXPECT_GT(one_in, 0);
  ns3::Simulator::Destroy();
}

}  // namespace
}  // namespace rlpos
