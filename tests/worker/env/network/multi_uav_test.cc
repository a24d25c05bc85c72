// Several UAVs: association, channels, the analytic model, the packet-level network, the
// positioners and the turn-taking env, on the shipped campus2 scenario (two clusters of six UEs).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "common/config/config_error.h"
#include "common/scenario/scenario_parser.h"
#include "tests/worker/env/network/shipped_scenario.h"
#include "worker/env/gym/reward.h"
#include "worker/env/network/association.h"
#include "worker/env/network/scenario_loading.h"
#include "worker/env/network/uav_network.h"
#include "worker/env/network/wifi_channel_plan.h"
#include "worker/env/uav_env/analytic_evaluator.h"
#include "worker/env/uav_env/uav_positioning_env.h"
#include "worker/positioning/positioners/positioners.h"

namespace rlpos {
namespace {

// One UAV low beside each cluster, with a clear view of most of it (the oracle's region).
const Placement kBesideClusters{{45, 100, 12}, {115, 0, 12}};

TEST(Association, BestSnrTiesToTheFirstAndAFixedUavWins) {
  Scenario s = LoadShipped("campus2");
  s.ues.resize(3);
  s.ues[2].uav = "north";
  // snr[u][i]
  const std::vector<std::vector<double>> snr{{10, 5, 0}, {20, 5, 30}};
  EXPECT_EQ(AssociateUes(s, snr), (std::vector<int>{1, 0, 0}));
}

TEST(UavChannels, DistinctUnlessGivenAndRefusedWhenTheBandRunsOut) {
  auto channels = [](const Scenario& s) {
    std::vector<int> out;
    for (const auto& plan : PlanUavChannels(s))
      out.push_back(plan.channel);
    return out;
  };
  EXPECT_EQ(channels(LoadShipped("campus2")), (std::vector<int>{50, 114}));
  EXPECT_EQ(channels(LoadShipped("urban3")), (std::vector<int>{42, 58, 106}));
  // ns-3 knows three 160 MHz channels in 5 GHz (50, 114, 163): a fourth UAV has none left.
  nlohmann::json four =
      ReadJsonFile(std::string(RLPOS_SOURCE_DIR) + "/campaigns/scenarios/campus2.json");
  four["uavs"].push_back({{"name", "west"}, {"position", {10, 10, 20}}});
  EXPECT_EQ(channels(ParseScenario(four)), (std::vector<int>{50, 114, 163}));
  four["uavs"].push_back({{"name", "east"}, {"position", {150, 10, 20}}});
  try {
    PlanUavChannels(ParseScenario(four));
    ADD_FAILURE() << "a fourth UAV on 160 MHz was accepted";
  } catch (const ConfigError& e) {
    EXPECT_EQ(e.path(), "/uavs/3");
    EXPECT_NE(e.problem().find("4 UAVs need distinct channels"), std::string::npos) << e.problem();
  }
  // UAVs given a channel keep it (the same one: they share it); the others get the rest.
  four["uavs"][2]["channel"] = 50;
  four["uavs"][3]["channel"] = 50;
  EXPECT_EQ(channels(ParseScenario(four)), (std::vector<int>{114, 163, 50, 50}));
  try {
    LoadShipped("campus2", {"uavs.1.channel=52"});
    ADD_FAILURE() << "channel 52 (not a 160 MHz channel) was accepted";
  } catch (const ConfigError& e) {
    // The value came from the override: the error names it, then the path.
    EXPECT_EQ(e.path(), "--set uavs.1.channel=52");
    EXPECT_EQ(e.problem().rfind("/uavs/1/channel: ", 0), 0u) << e.problem();
  }
}

// Demands of 150 Mbit/s per UE (1.8 Gbit/s): more than one 160 MHz channel carries.
std::vector<std::string> Saturated(std::vector<std::string> overrides) {
  for (int i = 0; i < 12; ++i)
    overrides.push_back("ues." + std::to_string(i) + ".demand={\"mbps\": 150}");
  return overrides;
}

TEST(AnalyticMultiUav, UesFollowTheBestUav) {
  AnalyticEvaluator analytic(LoadShipped("campus2", {"env.fidelity=analytic"}));
  const StepInfo beside = analytic.Evaluate(kBesideClusters);
  // North, on the west side, serves most of the west cluster w0-w5; south most of the east.
  EXPECT_GE(std::count(beside.serving.begin(), beside.serving.begin() + 6, 0), 4);
  EXPECT_GE(std::count(beside.serving.begin() + 6, beside.serving.end(), 1), 4);
  // Re-association as a UAV moves: south, moved over the west cluster, takes it.
  const StepInfo moved = analytic.Evaluate({{45, 100, 12}, {27, 30, 40}});
  EXPECT_GT(std::count(moved.serving.begin(), moved.serving.begin() + 6, 1),
            std::count(beside.serving.begin(), beside.serving.begin() + 6, 1));
}

TEST(AnalyticMultiUav, UavsOnOneChannelShareItsAirtime) {
  StepInfo apart, shared;
  {
    AnalyticEvaluator analytic(LoadShipped("campus2", Saturated({"env.fidelity=analytic"})));
    apart = analytic.Evaluate(kBesideClusters);
  }
  {
    AnalyticEvaluator analytic(LoadShipped(
        "campus2", Saturated({"env.fidelity=analytic", "uavs.0.channel=50", "uavs.1.channel=50"})));
    shared = analytic.Evaluate(kBesideClusters);
  }
  EXPECT_EQ(shared.serving, apart.serving);
  EXPECT_EQ(shared.n_los, apart.n_los);
  // Two channels carry more of the demand than one.
  EXPECT_GT(apart.throughput_mbps, 1.3 * shared.throughput_mbps)
      << apart.throughput_mbps << " vs " << shared.throughput_mbps;
}

TEST(PacketMultiUav, PerUavMetricsAddUpAndACommonChannelInterferes) {
  const auto short_run = Saturated({"simulation.duration=1", "simulation.warmup=0.5"});
  const RunMetrics apart = EvaluatePosition(LoadShipped("campus2", short_run), kBesideClusters);
  auto shared_overrides = short_run;
  shared_overrides.push_back("uavs.0.channel=50");
  shared_overrides.push_back("uavs.1.channel=50");
  const RunMetrics shared =
      EvaluatePosition(LoadShipped("campus2", shared_overrides), kBesideClusters);
  for (const RunMetrics* m : {&apart, &shared}) {
    ASSERT_EQ(m->uavs.size(), 2u);
    EXPECT_EQ(m->uavs[0].ues_served + m->uavs[1].ues_served, 12);
    EXPECT_NEAR(m->uavs[0].throughput_mbps + m->uavs[1].throughput_mbps,
                m->aggregate_throughput_mbps, 1e-9);
    EXPECT_EQ(m->uavs[0].n_los + m->uavs[1].n_los, m->n_los);
  }
  EXPECT_EQ(apart.uavs[0].uav.channel, 50);
  EXPECT_EQ(apart.uavs[1].uav.channel, 114);
  EXPECT_EQ(shared.uavs[1].uav.channel, 50);
  // Two BSSs on one channel contend for it: less than on two channels.
  EXPECT_GT(apart.aggregate_throughput_mbps, 1.3 * shared.aggregate_throughput_mbps)
      << apart.aggregate_throughput_mbps << " vs " << shared.aggregate_throughput_mbps;
  std::printf("campus2 beside the clusters: two channels %.1f Mbit/s, one channel %.1f Mbit/s\n",
              apart.aggregate_throughput_mbps, shared.aggregate_throughput_mbps);
}

TEST(PacketMultiUav, AFixedAssignmentHoldsAgainstTheSnr) {
  std::vector<std::string> overrides{"simulation.duration=1", "simulation.warmup=0.5"};
  for (int i = 0; i < 12; ++i)
    overrides.push_back("ues." + std::to_string(i) + ".uav=\"south\"");
  const RunMetrics m = EvaluatePosition(LoadShipped("campus2", overrides), kBesideClusters);
  EXPECT_EQ(m.uavs[0].ues_served, 0);
  EXPECT_EQ(m.uavs[1].ues_served, 12);
  EXPECT_DOUBLE_EQ(m.uavs[0].throughput_mbps, 0.0);
  EXPECT_GT(m.uavs[1].throughput_mbps, 0.0);
}

// Swapping the two UAVs makes every UE's best UAV the other one: each is handed over, and its
// flow resumes from its radio in the other UAV's BSS to a sink on that UAV. Returns the metrics
// before (0.5-1 s) and after (`resumed_from` + 1 s) the handover at 1 s.
std::pair<RunMetrics, RunMetrics> SwapTheUavs(const std::vector<std::string>& overrides,
                                              double resumed_from = 2.0) {
  const Scenario s = LoadShipped("campus2", Saturated(overrides));
  UavNetwork network(s, kBesideClusters, Handover::kOn);
  network.BeginMeasurement({0.5, 1.0});
  network.RunUntil(1.0);
  const RunMetrics settled = network.Measure();
  const std::vector<int> before = network.Association();

  network.SetUavPositions({kBesideClusters[1], kBesideClusters[0]});
  EXPECT_EQ(network.Reassociate(), 12);
  EXPECT_EQ(network.Handovers(), 12u);
  std::vector<int> swapped;
  for (int u : before)
    swapped.push_back(1 - u);
  EXPECT_EQ(network.Association(), swapped);

  network.BeginMeasurement({1.0, 2.0});
  network.RunUntil(2.0);
  const RunMetrics moving = network.Measure();
  network.RunUntil(resumed_from);
  network.BeginMeasurement({resumed_from, resumed_from + 1.0});
  network.RunUntil(resumed_from + 1.0);
  const RunMetrics resumed = network.Measure();
  EXPECT_EQ(network.Reassociate(), 0);  // nothing moved since
  // A UE that carries traffic does so from its radio associated with its new UAV's AP.
  const std::vector<int> aps = network.AssociatedAps();
  for (std::size_t i = 0; i < aps.size(); ++i) {
    if (resumed.ues[i].throughput_mbps > 0.0) {
      EXPECT_EQ(aps[i], swapped[i]) << resumed.ues[i].name;
    }
  }
  EXPECT_EQ(resumed.uavs[0].ues_served, settled.uavs[1].ues_served);
  std::printf(
      "campus2, all 12 UEs handed over at 1 s: %.1f Mbit/s before, %.1f over the next "
      "second, %.1f over [%g, %g] s\n",
      settled.aggregate_throughput_mbps, moving.aggregate_throughput_mbps,
      resumed.aggregate_throughput_mbps, resumed_from, resumed_from + 1.0);
  return {settled, resumed};
}

TEST(PacketMultiUav, SwappedUavsHandEveryUeOverAcrossChannels) {
  const auto [settled, resumed] = SwapTheUavs({});
  // w0 and e4 sit behind buildings from both UAVs here: out of reach (-24 dB), never associated.
  for (std::size_t i = 0; i < resumed.ues.size(); ++i) {
    const bool reachable = i != 0 && i != 10;
    EXPECT_EQ(settled.ues[i].throughput_mbps > 0.0, reachable) << settled.ues[i].name;
    EXPECT_EQ(resumed.ues[i].throughput_mbps > 0.0, reachable) << resumed.ues[i].name;
  }
  // Mirror images: the same links, each cluster on the other UAV's channel.
  EXPECT_GT(resumed.aggregate_throughput_mbps, 0.9 * settled.aggregate_throughput_mbps)
      << resumed.aggregate_throughput_mbps << " vs " << settled.aggregate_throughput_mbps;
}

TEST(PacketMultiUav, SwappedUavsHandEveryUeOverOnACommonChannel) {
  // One saturated channel for both BSSs: a few UEs starve, before and after alike.
  const auto [settled, resumed] = SwapTheUavs({"uavs.0.channel=50", "uavs.1.channel=50"});
  EXPECT_GT(resumed.aggregate_throughput_mbps, 0.75 * settled.aggregate_throughput_mbps)
      << resumed.aggregate_throughput_mbps << " vs " << settled.aggregate_throughput_mbps;
}

TEST(PacketMultiUav, SwappedUavsHandEveryUeOverWithTcp) {
  // Saturated TCP uplinks share the channel unevenly (a few flows carry most of it, before the
  // handover as after); new connections whose SYN is lost wait for TCP's retry, so look later.
  const auto [settled, resumed] = SwapTheUavs({"traffic.protocol=\"tcp_bulk\""}, 4.0);
  EXPECT_GT(resumed.aggregate_throughput_mbps, 0.5 * settled.aggregate_throughput_mbps)
      << resumed.aggregate_throughput_mbps << " vs " << settled.aggregate_throughput_mbps;
}

TEST(PacketMultiUav, AFixedAssignmentIsNeverHandedOver) {
  std::vector<std::string> overrides;
  for (int i = 0; i < 12; ++i)
    overrides.push_back("ues." + std::to_string(i) + ".uav=\"south\"");
  UavNetwork network(LoadShipped("campus2", overrides), kBesideClusters, Handover::kOn);
  network.RunUntil(0.5);
  network.SetUavPositions({kBesideClusters[1], kBesideClusters[0]});
  EXPECT_EQ(network.Reassociate(), 0);
  EXPECT_EQ(network.Association(), std::vector<int>(12, 1));
}

TEST(PacketMultiUav, OnlyANetworkBuiltForHandoverReassociates) {
  UavNetwork network(LoadShipped("campus2"), kBesideClusters);
  EXPECT_THROW(network.Reassociate(), std::logic_error);
}

TEST(Positioners, CentroidsOfTwoClustersAboveTheirTowers) {
  const Scenario s = LoadShipped("campus2");
  const Placement p = CentroidPlacement(s);
  ASSERT_EQ(p.size(), 2u);
  std::vector<double> xs{p[0].x, p[1].x};
  std::sort(xs.begin(), xs.end());
  // The clusters' centroids lie over the two 30 m lab towers, x in [20, 35] and [125, 140].
  EXPECT_GT(xs[0], 20);
  EXPECT_LT(xs[0], 35);
  EXPECT_GT(xs[1], 125);
  EXPECT_LT(xs[1], 140);
  EXPECT_DOUBLE_EQ(p[0].z, 35);  // tallest building 30 m + 5 m
  const Placement again = CentroidPlacement(s);
  EXPECT_EQ(again[0].x, p[0].x);
  EXPECT_EQ(again[1].y, p[1].y);
}

TEST(Positioners, OracleEndsWhereNoSingleUavCanImprove) {
  const Scenario s = LoadShipped("campus2", {"env.fidelity=analytic"});
  OracleOptions options;
  options.grid_step = 20;
  options.packet_candidates = 0;
  options.starts = 4;
  const auto ranked = OracleSearch(s, options);
  ASSERT_FALSE(ranked.empty());
  for (std::size_t i = 1; i < ranked.size(); ++i)
    EXPECT_GE(ranked[i - 1].analytic_reward, ranked[i].analytic_reward);
  const ScoredPlacement& best = ranked.front();
  const auto reward = MakeReward(s.env.reward);
  AnalyticEvaluator analytic(s);
  auto score = [&](const Placement& p) {
    const StepInfo info = analytic.Evaluate(p);
    return (*reward)(RewardInputOf(s, info.n_los, info.throughput_mbps, info.demands_met));
  };
  EXPECT_NEAR(score(best.placement), best.analytic_reward, 1e-12);
  EXPECT_GE(best.analytic_reward, score(BaselinePlacement(s)));
  EXPECT_GE(best.analytic_reward, score(CentroidPlacement(s)));
  // The stated guarantee: a coordinate-wise optimum on the grid.
  for (std::size_t u = 0; u < 2; ++u) {
    for (const Vec3& g : ZoneGrid(s, u, options.grid_step)) {
      Placement moved = best.placement;
      moved[u] = g;
      if (std::hypot(moved[0].x - moved[1].x, moved[0].y - moved[1].y, moved[0].z - moved[1].z) <
          kMinUavSeparation)
        continue;
      EXPECT_LE(score(moved), best.analytic_reward + 1e-12)
          << "UAV " << u << " to " << g.x << "," << g.y << "," << g.z;
    }
  }
}

TEST(TurnTakingEnv, UavsMoveInTurnAndNeverOntoEachOther) {
  // The two UAVs 5 m apart on x: north's "right" would land on south.
  const Scenario s =
      LoadShipped("campus2", {"env.fidelity=analytic", "uavs.0.position=[100, 50, 40]",
                              "uavs.1.position=[105, 50, 40]",
                              "env.observations=[\"x\", \"y\", \"z\", \"n_los\"]"});
  UavPositioningEnv env(s);
  const auto action = [&](const std::string& name) {
    return static_cast<int>(std::find(s.env.actions.begin(), s.env.actions.end(), name) -
                            s.env.actions.begin());
  };
  std::vector<double> obs = env.Reset(1);
  ASSERT_EQ(obs.size(), env.ObservationSpace().Dim());
  ASSERT_EQ(obs.size(), 2u * 3 + 1 + 2);  // x, y, z of each, nLoS, whose turn
  EXPECT_EQ(obs[7], 1.0);
  EXPECT_EQ(obs[8], 0.0);
  const ActionMask mask = env.ValidActions();
  ASSERT_FALSE(mask.empty());
  EXPECT_EQ(mask[static_cast<std::size_t>(action("right"))], 0);  // onto south
  EXPECT_EQ(mask[static_cast<std::size_t>(action("left"))], 1);
  StepResult r = env.Step(action("right"));  // refused: stays
  EXPECT_EQ(r.info.positions[0].x, 100);
  EXPECT_EQ(r.info.active_uav, 1);
  EXPECT_EQ(r.observation[8], 1.0);
  r = env.Step(action("right"));  // south's turn
  EXPECT_EQ(r.info.positions[0].x, 100);
  EXPECT_EQ(r.info.positions[1].x, 110);
  r = env.Step(action("up"));  // north again
  EXPECT_EQ(r.info.positions[0].z, 45);
  EXPECT_EQ(r.info.positions[1].z, 40);
  EXPECT_TRUE(env.ObservationSpace().Contains(r.observation));
}

// A packet-level episode hands UEs over as the analytic model re-associates them: the same
// moves give the same serving UAVs, step by step, including the steps where they change.
TEST(TurnTakingEnv, PacketEpisodesReassociateAsTheAnalyticModelDoes) {
  const std::vector<std::string> start{"uavs.0.position=[100, 50, 40]",
                                       "uavs.1.position=[105, 50, 40]"};
  auto analytic_overrides = start;
  analytic_overrides.push_back("env.fidelity=analytic");
  const Scenario analytic_scenario = LoadShipped("campus2", analytic_overrides);
  const auto action = [&](const std::string& name) {
    const auto& actions = analytic_scenario.env.actions;
    return static_cast<int>(std::find(actions.begin(), actions.end(), name) - actions.begin());
  };
  // North flies west (its turns), south stays: UEs of the west cluster change UAV on the way.
  const std::vector<int> moves{action("left"), action("stay"), action("left"), action("stay"),
                               action("left"), action("stay"), action("left"), action("stay")};
  UavPositioningEnv analytic(analytic_scenario);
  analytic.Reset(1);
  std::vector<std::vector<int>> serving{analytic.LastInfo().serving};
  for (int a : moves)
    serving.push_back(analytic.Step(a).info.serving);
  int changes = 0;
  for (std::size_t k = 1; k < serving.size(); ++k)
    changes += serving[k] != serving[k - 1];
  ASSERT_GT(changes, 0) << "the moves must change some UE's UAV";

  auto packet_overrides = start;
  packet_overrides.push_back("env.fidelity=packet");
  UavPositioningEnv packet(LoadShipped("campus2", packet_overrides));
  packet.Reset(1);
  EXPECT_EQ(packet.LastInfo().serving, serving[0]);
  for (std::size_t k = 0; k < moves.size(); ++k)
    EXPECT_EQ(packet.Step(moves[k]).info.serving, serving[k + 1]) << "after step " << k + 1;
}

TEST(TurnTakingEnv, TurnsOfSeveralSteps) {
  const Scenario s = LoadShipped("campus2", {"env.fidelity=analytic", "env.turn_steps=2"});
  UavPositioningEnv env(s);
  const int up = static_cast<int>(std::find(s.env.actions.begin(), s.env.actions.end(), "up") -
                                  s.env.actions.begin());
  env.Reset(1);
  std::vector<int> moved;
  for (int step = 0; step < 6; ++step) {
    const Placement before = env.LastInfo().positions;
    const StepResult r = env.Step(up);
    moved.push_back(r.info.positions[0].z != before[0].z ? 0 : 1);
  }
  EXPECT_EQ(moved, (std::vector<int>{0, 0, 1, 1, 0, 0}));
}

}  // namespace
}  // namespace rlpos
