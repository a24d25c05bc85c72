// Packet level: ns-3 plays each moving UE's trajectory exactly as common/mobility computes it
// (the analytic fidelity's positions), and a run with moving UEs is reproducible.
#include <gtest/gtest.h>

#include <cmath>

#include "common/mobility/ue_trajectories.h"
#include "common/scenario/scenario_parser.h"
#include "tests/worker/env/network/shipped_scenario.h"
#include "worker/env/network/uav_network.h"

namespace rlpos {
namespace {

// Scenario B with its four UEs walking fast, one model each, for 2 s.
Scenario MovingB() {
  return LoadShipped(
      "b", {"simulation.duration=2", "simulation.warmup=0.5",
            R"(ues.0.mobility={"model": "random_waypoint", "speed": [3, 5], "pause": 0.2})",
            R"(ues.1.mobility={"model": "gauss_markov", "speed": 3, "alpha": 0.5, "step": 0.3})",
            R"(ues.2.mobility={"model": "crowd", "target": [35, 85], "speed": 4, "start": 0.5,
                               "dwell": 0.3})",
            R"(ues.3.mobility={"model": "random_walk", "speed": 3, "change_interval": 0.4})"});
}

TEST(UeMobility, Ns3SeesTheTrajectoriesOfTheModel) {
  const Scenario s = MovingB();
  const auto trajectories = UeTrajectories(s);
  UavNetwork network(s, s.InitialPlacement());
  std::vector<double> moved(s.ues.size(), 0.0);
  // Off the waypoints' grid too: 0.037 s steps.
  for (double t = 0.0; t <= 1.9; t += 0.037) {
    network.RunUntil(t);
    const auto seen = network.UePositions();
    ASSERT_EQ(seen.size(), s.ues.size());
    for (std::size_t i = 0; i < seen.size(); ++i) {
      const Vec3 expected = trajectories[i].PositionAt(network.Now());
      EXPECT_NEAR(seen[i].x, expected.x, 1e-6) << "UE " << i << " at " << network.Now();
      EXPECT_NEAR(seen[i].y, expected.y, 1e-6) << "UE " << i << " at " << network.Now();
      EXPECT_NEAR(seen[i].z, expected.z, 1e-9) << "UE " << i << " at " << network.Now();
      moved[i] = std::max(
          moved[i], std::hypot(seen[i].x - s.ues[i].position.x, seen[i].y - s.ues[i].position.y));
    }
  }
  for (std::size_t i = 0; i < moved.size(); ++i)
    EXPECT_GT(moved[i], 1.0) << "UE " << i << " never walked";
}

TEST(UeMobility, ARunWithMovingUesIsReproducible) {
  const Scenario s = MovingB();
  const RunMetrics first = EvaluatePosition(s, s.InitialPlacement());
  const RunMetrics second = EvaluatePosition(s, s.InitialPlacement());
  EXPECT_EQ(ToJson(first), ToJson(second));
  EXPECT_GT(first.aggregate_throughput_mbps, 0.0);
}

}  // namespace
}  // namespace rlpos
