// The analytic fidelity as a value (worker/env/analytic): the same numbers as the ns-3
// network it replaces (UavNetwork built, never run: LinksTo, McsSnrThresholdsDb,
// MpduSuccessRate, scored as the evaluator always did), and several alive or running at once.
#include "worker/env/analytic/analytic_channel.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <iostream>
#include <random>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include "common/config/config_error.h"
#include "common/phy/airtime_model.h"
#include "common/phy/mcs_table.h"
#include "common/scenario/scenario_checks.h"
#include "common/scenario_generator/scenario_generator.h"
#include "worker/env/gym/reward.h"
#include "worker/env/network/scenario_loading.h"
#include "worker/env/network/uav_network.h"
#include "worker/env/uav_env/analytic_evaluator.h"
#include "worker/env/uav_env/uav_positioning_env.h"

namespace rlpos {
namespace {

constexpr double kTolerance = 1e-9;
constexpr int kTrajectorySteps = 500;

Scenario Shipped(const std::string& name, const std::vector<std::string>& overrides = {}) {
  return LoadScenario(std::string(RLPOS_SOURCE_DIR) + "/campaigns/scenarios/" + name, overrides);
}

// The links the evaluator got from the UavNetwork before it became a value.
std::vector<UeLink> ReferenceLinks(UavNetwork& network, const std::vector<double>& thresholds,
                                   std::size_t uav, const Vec3& position) {
  const Scenario& s = network.scenario();
  const PhyProfile phy{s.wifi.standard, s.wifi.width_mhz, s.wifi.guard_interval_ns,
                       s.wifi.spatial_streams};
  network.SetUavPosition(uav, position);
  const auto states = network.LinksTo(uav);
  std::vector<UeLink> links;
  for (std::size_t i = 0; i < states.size(); ++i) {
    UeLink link;
    link.los = states[i].los;
    link.snr_db = states[i].snr_db;
    link.demand_met = CheckDemand(phy, s.ues[i].demand_mbps, link.snr_db).met;
    int mcs = -1;
    while (mcs + 1 < static_cast<int>(thresholds.size()) && link.snr_db >= thresholds[mcs + 1])
      ++mcs;
    if (mcs >= 0) {
      link.phy_rate_mbps = McsDataRateMbps(phy, mcs);
      link.mpdu_success =
          network.MpduSuccessRate(mcs, link.snr_db, MpduBytes(s.traffic.packet_size));
    }
    links.push_back(link);
  }
  return links;
}

double RewardAt(const Scenario& s, const StepInfo& info) {
  return (*MakeReward(s.env.reward))(
      RewardInputOf(s, info.n_los, info.throughput_mbps, info.demands_met));
}

// What a trajectory went through, so that a test can tell it met the cases it means to check.
struct Seen {
  int los = 0, nlos = 0;
  int uav_indoors = 0;  // UAV positions inside a building
  double max_snr_db = -1e9;
};

// A random walk of every UAV inside its zone, a move of env.step (or none) per axis and step.
Seen ExpectSameAsUavNetwork(const Scenario& s, std::uint32_t seed) {
  SCOPED_TRACE(s.name);
  Seen seen;
  AnalyticEvaluator evaluator(s);
  UavNetwork network(s, s.InitialPlacement());
  const std::vector<double> thresholds = network.McsSnrThresholdsDb();
  std::mt19937 rng(seed);
  std::uniform_int_distribution<int> move(-1, 1);
  Placement placement = s.InitialPlacement();
  for (int step = 0; step < kTrajectorySteps; ++step) {
    std::vector<std::vector<UeLink>> ours(placement.size()), theirs(placement.size());
    std::vector<const std::vector<UeLink>*> our_views, their_views;
    for (std::size_t u = 0; u < placement.size(); ++u) {
      const Box& zone = s.uavs[u].zone;
      Vec3& p = placement[u];
      p.x = std::clamp(p.x + move(rng) * s.env.step, zone.xmin, zone.xmax);
      p.y = std::clamp(p.y + move(rng) * s.env.step, zone.ymin, zone.ymax);
      p.z = std::clamp(p.z + move(rng) * s.env.step, zone.zmin, zone.zmax);
      ours[u] = evaluator.LinksAt(u, p);
      theirs[u] = ReferenceLinks(network, thresholds, u, p);
      seen.uav_indoors += BuildingContaining(s, p) >= 0 ? 1 : 0;
      EXPECT_EQ(ours[u].size(), theirs[u].size());
      if (ours[u].size() != theirs[u].size())
        return seen;
      for (std::size_t i = 0; i < ours[u].size(); ++i) {
        const UeLink &a = ours[u][i], &b = theirs[u][i];
        const bool same = a.los == b.los && std::abs(a.snr_db - b.snr_db) <= kTolerance &&
                          std::abs(a.mpdu_success - b.mpdu_success) <= kTolerance &&
                          a.phy_rate_mbps == b.phy_rate_mbps && a.demand_met == b.demand_met;
        if (!same) {
          ADD_FAILURE() << "step " << step << ", UAV " << u << " at (" << p.x << ", " << p.y << ", "
                        << p.z << "), UE " << i << ": LoS " << a.los << " / " << b.los << ", SNR "
                        << a.snr_db << " / " << b.snr_db << " dB, MPDU success " << a.mpdu_success
                        << " / " << b.mpdu_success;
          return seen;
        }
        (a.los ? seen.los : seen.nlos) += 1;
        seen.max_snr_db = std::max(seen.max_snr_db, a.snr_db);
      }
      our_views.push_back(&ours[u]);
      their_views.push_back(&theirs[u]);
    }
    const StepInfo theirs_info = evaluator.Score(placement, their_views);
    const StepInfo ours_info = evaluator.Evaluate(placement);
    EXPECT_EQ(ours_info.serving, theirs_info.serving) << "step " << step;
    const double ours_reward = RewardAt(s, ours_info), theirs_reward = RewardAt(s, theirs_info);
    if (std::abs(ours_reward - theirs_reward) > kTolerance) {
      ADD_FAILURE() << "step " << step << ": reward " << ours_reward << " / " << theirs_reward;
      return seen;
    }
  }
  return seen;
}

TEST(AnalyticChannel, ThresholdsAreTheNetworks) {
  for (const auto& name : {"b.json", "urban3.json"}) {
    const Scenario s = Shipped(name);
    std::vector<double> theirs;
    {
      UavNetwork network(s, s.InitialPlacement());
      theirs = network.McsSnrThresholdsDb();
    }
    AnalyticChannel channel(s);
    EXPECT_EQ(channel.McsSnrThresholdsDb(), theirs) << name;
  }
}

class SameNumbers : public ::testing::TestWithParam<std::string> {};

TEST_P(SameNumbers, AsTheNs3NetworkOnAShippedScenario) {
  const Scenario s = Shipped(GetParam());
  const Seen seen = ExpectSameAsUavNetwork(s, 1);
  EXPECT_GT(seen.los, 0);
  if (!s.buildings.empty()) {
    EXPECT_GT(seen.nlos, 0);
  }
}

INSTANTIATE_TEST_SUITE_P(AnalyticChannel, SameNumbers,
                         ::testing::Values("a.json", "b.json", "c.json", "campus2.json",
                                           "urban3.json"));

// Other PHYs than the shipped 802.11ac: HE's MCS 10-11 have no AWGN table in ns-3 (its
// fallback model), HT counts MCSs over two streams.
TEST(AnalyticChannel, SameNumbersOnOtherPhys) {
  ExpectSameAsUavNetwork(Shipped("b.json", {"wifi.standard=802.11ax", "wifi.guard_interval=800"}),
                         2);
  ExpectSameAsUavNetwork(Shipped("b.json", {"wifi.standard=802.11n", "wifi.width=40",
                                            "wifi.channel=38", "wifi.spatial_streams=2"}),
                         3);
}

// Generated scenarios of every style, with one to three UAVs. The unit test takes the first
// RLPOS_GENERATED_SCENARIOS (default all 100: about 20 s).
TEST(AnalyticChannel, SameNumbersOnGeneratedScenarios) {
  int count = 100;
  if (const char* n = std::getenv("RLPOS_GENERATED_SCENARIOS"))
    count = std::atoi(n);
  Seen all;
  for (int k = 1; k <= count && !HasFailure(); ++k) {
    GeneratorOptions options;
    options.seed = static_cast<std::uint64_t>(k);
    options.uavs = 1 + k % 3;
    const Seen seen =
        ExpectSameAsUavNetwork(GenerateScenario(options).scenario, static_cast<std::uint32_t>(k));
    all.los += seen.los;
    all.nlos += seen.nlos;
    all.uav_indoors += seen.uav_indoors;
  }
  EXPECT_GT(all.los, 0);
  EXPECT_GT(all.nlos, 0);
  EXPECT_GT(all.uav_indoors, 0);  // the indoor rules too
  std::cout << count << " generated scenarios: " << all.los << " LoS and " << all.nlos
            << " NLoS links, " << all.uav_indoors << " UAV positions inside a building\n";
}

struct Trajectory {
  std::vector<std::vector<double>> observations;
  std::vector<double> rewards;
  bool operator==(const Trajectory& o) const {
    return observations == o.observations && rewards == o.rewards;
  }
};

// An episode of random actions, begun by Reset(seed).
class Walker {
 public:
  Walker(const Scenario& s, std::uint64_t seed) : env_(s), rng_(static_cast<std::uint32_t>(seed)) {
    trajectory_.observations.push_back(env_.Reset(seed));
  }
  void Step() {
    std::uniform_int_distribution<int> action(0, env_.ActionSpace().n - 1);
    StepResult r = env_.Step(action(rng_));
    trajectory_.observations.push_back(std::move(r.observation));
    trajectory_.rewards.push_back(r.reward);
  }
  const Trajectory& trajectory() const { return trajectory_; }

 private:
  UavPositioningEnv env_;
  std::mt19937 rng_;
  Trajectory trajectory_;
};

constexpr int kEnvSteps = 200;

Trajectory Alone(const Scenario& s, std::uint64_t seed) {
  Walker walker(s, seed);
  for (int k = 0; k < kEnvSteps; ++k)
    walker.Step();
  return walker.trajectory();
}

// Two envs alive at once, stepped in turn: B (five buildings) and A (none), so that one
// scenario's buildings leaking into the other's links would show.
TEST(AnalyticChannel, TwoEnvsAtOnceGiveEachOnesTrajectory) {
  const Scenario b = Shipped("b.json", {"env.fidelity=analytic"});
  const Scenario a = Shipped("a.json", {"env.fidelity=analytic"});
  const Trajectory b_alone = Alone(b, 7);
  const Trajectory a_alone = Alone(a, 8);
  Walker on_b(b, 7);
  Walker on_a(a, 8);
  for (int k = 0; k < kEnvSteps; ++k) {
    on_b.Step();
    on_a.Step();
  }
  EXPECT_TRUE(on_b.trajectory() == b_alone);
  EXPECT_TRUE(on_a.trajectory() == a_alone);
}

// Four threads, each loading B and stepping an env of its own, at once: each trajectory as one
// thread alone gives it.
TEST(AnalyticChannel, FourThreadsGiveOneThreadsNumbers) {
  const Scenario b = Shipped("b.json", {"env.fidelity=analytic"});
  std::vector<Trajectory> alone;
  for (std::uint64_t seed = 1; seed <= 4; ++seed)
    alone.push_back(Alone(b, seed));
  std::vector<Trajectory> threaded(4);
  std::vector<std::thread> threads;
  for (std::uint64_t seed = 1; seed <= 4; ++seed) {
    threads.emplace_back([&threaded, seed] {
      threaded[seed - 1] = Alone(Shipped("b.json", {"env.fidelity=analytic"}), seed);
    });
  }
  for (auto& t : threads)
    t.join();
  for (std::size_t k = 0; k < 4; ++k)
    EXPECT_TRUE(threaded[k] == alone[k]) << "thread " << k;
}

// Loss models the analytic model cannot follow are refused at construction, one line each:
// the packet level drew a new loss per call from a random one (today's analytic path did too).
TEST(AnalyticChannel, RefusesLossModelsItCannotFollow) {
  const Scenario b = Shipped("b.json");
  const auto refusal = [&](ObjectSpec propagation) -> std::string {
    Scenario s = b;
    s.propagation = std::move(propagation);
    try {
      AnalyticChannel channel(s);
    } catch (const ConfigError& e) {
      return e.describe();
    }
    return "accepted";
  };
  const ObjectSpec aware = b.propagation;
  ObjectSpec random{"ns3::ObstacleAwarePropagationLossModel", aware.attributes};
  random.attributes["LosModel"] = {{"type", "ns3::NakagamiPropagationLossModel"}};
  EXPECT_EQ(refusal(random),
            "/propagation: ns3::ObstacleAwarePropagationLossModel draws random numbers: the "
            "analytic fidelity needs one loss per link and position; use packet fidelity");
  EXPECT_EQ(refusal({"ns3::HybridBuildingsPropagationLossModel", nlohmann::json::object()}),
            "/propagation: ns3::HybridBuildingsPropagationLossModel reads ns-3's process-wide "
            "building list, which the analytic fidelity does not build; use packet fidelity");
  ObjectSpec condition{"ns3::ObstacleAwarePropagationLossModel", aware.attributes};
  condition.attributes["ChannelConditionModel"] = {
      {"type", "ns3::ThreeGppUmaChannelConditionModel"}};
  EXPECT_EQ(refusal(condition),
            "/propagation/attributes/ChannelConditionModel: the analytic fidelity decides LoS "
            "from the buildings: ns3::ObstaclesChannelConditionModel or "
            "ns3::BuildingsChannelConditionModel only; use packet fidelity");
  EXPECT_EQ(refusal({"ns3::FriisPropagationLossModel", nlohmann::json::object()}), "accepted");
}

// Packet fidelity keeps one network per process, and says so.
TEST(AnalyticChannel, ASecondPacketNetworkSaysWhy) {
  const Scenario b = Shipped("b.json");
  UavNetwork first(b, b.InitialPlacement());
  try {
    UavNetwork second(b, b.InitialPlacement());
    FAIL() << "a second packet-level network was built";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("process of its own"), std::string::npos) << e.what();
  }
  AnalyticEvaluator beside(b);  // the analytic model still works beside it
  EXPECT_EQ(beside.Evaluate(b.InitialPlacement()).snr_db.size(), b.ues.size());
}

}  // namespace
}  // namespace rlpos
