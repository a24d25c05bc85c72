// The model observations ("coverage" and "lookahead"): the values are the analytic
// model's rewards where they say, the map is no better than the oracle's grid, and the map of one
// UAV is worked out once.
#include "worker/env/uav_env/model_observations.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "common/scenario/building_obstacles.h"
#include "common/scenario/scenario_checks.h"
#include "common/scenario_generator/scenario_generator.h"
#include "worker/env/gym/general_observation.h"
#include "worker/env/gym/lattice_route.h"
#include "worker/env/gym/moves.h"
#include "worker/env/gym/multi_agent.h"
#include "worker/env/gym/reward.h"
#include "worker/env/network/scenario_loading.h"
#include "worker/env/uav_env/analytic_evaluator.h"
#include "worker/env/uav_env/uav_positioning_env.h"

namespace rlpos {
namespace {

// With 40 m moves the pointer (clipped to kPointerStepLimit moves) spans a generated zone.
Scenario Observing(Scenario s, std::vector<std::string> fields) {
  s.env.fidelity = "analytic";
  s.env.step = 40;
  s.env.observations = std::move(fields);
  s.env.coverage_map = 4;
  return s;
}

Scenario GeneratedUrban(int uavs) {
  GeneratorOptions options;
  options.seed = 77;
  options.style = GeneratorStyle::kUrban;
  options.uavs = uavs;
  return GenerateScenario(options).scenario;
}

// The best reward over the zone's move grid, by brute force.
double GridBest(const Scenario& s) {
  AnalyticEvaluator model(s);
  const auto reward = MakeReward(s.env.reward);
  double best = 0.0;
  const Box& z = s.uavs[0].zone;
  const Vec3& o = s.uavs[0].initial;
  const double step = s.env.step;
  for (double x = o.x - step * std::floor((o.x - z.xmin) / step); x <= z.xmax; x += step) {
    for (double y = o.y - step * std::floor((o.y - z.ymin) / step); y <= z.ymax; y += step) {
      for (double h = o.z - step * std::floor((o.z - z.zmin) / step); h <= z.zmax; h += step) {
        if (BuildingContaining(s, {x, y, h}) >= 0)
          continue;
        const StepInfo i = model.Evaluate({{x, y, h}});
        best =
            std::max(best, (*reward)(RewardInputOf(s, i.n_los, i.throughput_mbps, i.demands_met)));
      }
    }
  }
  return best;
}

TEST(ModelObservations, TheMapsBestIsAModelRewardWhereItsPointerLeadsAndNoBetterThanTheGrid) {
  const Scenario s = Observing(GeneratedUrban(1), {"coverage"});
  UavPositioningEnv env(s);
  const std::vector<double> o = env.Reset(1);
  ASSERT_EQ(o.size(), 2u * 16 + 3);
  const double bound = CoverageRewardBound(s);
  const double best = *std::max_element(o.begin(), o.begin() + 16) * bound;
  const Vec3& at = env.LastInfo().positions[0];
  const Vec3 pointed{at.x + o[32] * s.env.step, at.y + o[33] * s.env.step,
                     at.z + o[34] * s.env.step};
  EXPECT_NEAR(AnalyticReward(s, {pointed}), best, 1e-12);
  EXPECT_LE(best, GridBest(s) + 1e-12);
  EXPECT_GT(best, 0.0);
  // Altitudes are within [0, 1]; the map stays while the UAV moves, the pointer follows it.
  for (int k = 16; k < 32; ++k) {
    EXPECT_GE(o[static_cast<std::size_t>(k)], 0.0);
    EXPECT_LE(o[static_cast<std::size_t>(k)], 1.0);
  }
  const StepResult moved = env.Step(0);  // up
  EXPECT_TRUE(std::equal(o.begin(), o.begin() + 32, moved.observation.begin()));
  const Vec3& now = moved.info.positions[0];
  EXPECT_NEAR(moved.observation[34] * s.env.step, pointed.z - now.z, 1e-9);
}

TEST(ModelObservations, EachMovesValueIsTheRewardItWouldReachMinusTheRewardHere) {
  const Scenario s = Observing(GeneratedUrban(1), {"lookahead"});
  UavPositioningEnv env(s);
  env.Reset(1);
  const double bound = CoverageRewardBound(s);
  const Obstacles buildings = BuildingObstacles(s.buildings);
  for (int step = 0; step < 5; ++step) {
    const StepResult here = env.Step(static_cast<int>(step % 2 == 0 ? 4 : 2));  // left, forward
    const std::vector<double> look = here.observation;
    ASSERT_EQ(look.size(), s.env.actions.size());
    for (std::size_t a = 0; a < look.size(); ++a) {
      const Placement from = here.info.positions;
      const Placement to =
          ApplyDisplacement(s, buildings, 0, MoveDisplacement(s, static_cast<int>(a)), from);
      const double expected =
          std::clamp(kLookaheadGain * (AnalyticReward(s, to) - here.reward) / bound, -1.0, 1.0);
      EXPECT_NEAR(look[a], expected, 1e-12) << "move " << s.env.actions[a] << " step " << step;
    }
  }
}

TEST(ModelObservations, SeveralUavsEachLookFromTheirOwnPosition) {
  Scenario s = Observing(GeneratedUrban(2), {"coverage"});
  s.env.coverage_map = 3;
  UavPositioningEnv env(s);
  env.Reset(1);
  const auto views = env.AgentObservations();
  ASSERT_EQ(views.size(), 2u);
  const double bound = CoverageRewardBound(s);
  const Placement& p = env.LastInfo().positions;
  for (std::size_t u = 0; u < 2; ++u) {
    const std::vector<double>& v = views[u];
    ASSERT_EQ(v.size(), 2u * 9 + 3);
    // UAV u's map is of its own zone, the other UAV where it is: its best is where its pointer
    // leads UAV u.
    Placement there = p;
    there[u] = {p[u].x + v[18] * s.env.step, p[u].y + v[19] * s.env.step,
                p[u].z + v[20] * s.env.step};
    EXPECT_NEAR(AnalyticReward(s, there), *std::max_element(v.begin(), v.begin() + 9) * bound,
                1e-12)
        << "UAV " << u;
  }
  EXPECT_NE(views[0], views[1]);
}

// "to_best" in env.actions: flown from the baseline it reaches where the pointer leads, the map's
// best, one move at a time, and is masked off there; its lookahead is the reward change of the
// move it makes.
TEST(ModelObservations, ToBestFliesToTheMapsBestAndItsLookaheadIsThatMovesChange) {
  Scenario s = Observing(GeneratedUrban(1), {"coverage", "lookahead"});
  s.env.step = 5;
  s.env.actions.push_back("to_best");
  const int to_best = static_cast<int>(s.env.actions.size()) - 1;
  const double bound = CoverageRewardBound(s);
  UavPositioningEnv env(s);
  std::vector<double> o = env.Reset(1);
  const std::size_t cells = 16, pointer = 2 * cells, look = pointer + 3;
  const double map_best = *std::max_element(o.begin(), o.begin() + cells) * bound;
  double reward = AnalyticReward(s, env.LastInfo().positions);
  int moves = 0;
  for (; moves < 200; ++moves) {
    const ActionMask mask = env.ValidActions();
    ASSERT_FALSE(mask.empty());
    if (!mask[static_cast<std::size_t>(to_best)])
      break;
    const Placement from = env.LastInfo().positions;
    const StepResult r = env.Step(to_best);
    const Vec3& a = from[0];
    const Vec3& b = r.info.positions[0];
    const int axes = (a.x != b.x) + (a.y != b.y) + (a.z != b.z);
    EXPECT_EQ(axes, 1) << "move " << moves;
    EXPECT_LE(std::abs(b.x - a.x) + std::abs(b.y - a.y) + std::abs(b.z - a.z), s.env.step + 1e-9);
    // The lookahead the move was chosen on (before it) said where it would lead.
    EXPECT_NEAR(o[look + static_cast<std::size_t>(to_best)],
                std::clamp(kLookaheadGain * (r.reward - reward) / bound, -1.0, 1.0), 1e-12)
        << "move " << moves;
    o = r.observation;
    reward = r.reward;
  }
  EXPECT_GT(moves, 3);
  EXPECT_LT(moves, 200);
  EXPECT_EQ(o[pointer], 0.0);
  EXPECT_EQ(o[pointer + 1], 0.0);
  EXPECT_EQ(o[pointer + 2], 0.0);
  EXPECT_NEAR(reward, map_best, 1e-12);
}

// With several UAVs moving at once each flies towards its own map's best, also when nothing asked
// for the others' observations since the last move.
TEST(ModelObservations, ToBestOfEachUavMovingAtOnceFollowsItsOwnPointer) {
  Scenario s = Observing(GeneratedUrban(2), {"coverage"});
  s.env.step = 5;
  s.env.coverage_map = 3;
  s.env.actions.push_back("to_best");
  const int to_best = static_cast<int>(s.env.actions.size()) - 1;
  UavPositioningEnv env(s), told(s);
  env.Reset(1);
  told.Reset(1);
  const Obstacles buildings = BuildingObstacles(s.buildings);
  std::vector<LatticeRoute> routes{{s, buildings, 0}, {s, buildings, 1}};
  for (int step = 0; step < 4; ++step) {
    const auto views = told.AgentObservations();
    const Placement from = told.LastInfo().positions;
    std::vector<Vec3> moves;
    for (std::size_t u = 0; u < 2; ++u) {
      const Vec3 target{from[u].x + views[u][18] * s.env.step,
                        from[u].y + views[u][19] * s.env.step,
                        from[u].z + views[u][20] * s.env.step};
      moves.push_back(routes[u].NextMove(target, from));
    }
    const JointStepResult r = env.JointStep({to_best, to_best});
    told.JointStep({to_best, to_best});
    const Placement expected = ApplyJointDisplacement(s, buildings, moves, from);
    for (std::size_t u = 0; u < 2; ++u) {
      EXPECT_EQ(r.info.positions[u].x, expected[u].x) << "UAV " << u << " step " << step;
      EXPECT_EQ(r.info.positions[u].y, expected[u].y) << "UAV " << u << " step " << step;
      EXPECT_EQ(r.info.positions[u].z, expected[u].z) << "UAV " << u << " step " << step;
    }
  }
}

// env.coverage_refine: the pointer leads to the best column within that many moves (x and y) of
// the map's best cell's column, at every altitude, or stays on the cell's when none beats it.
TEST(ModelObservations, TheRefinedPointerLeadsToTheBestColumnAroundTheMapsBest) {
  int moved = 0;
  for (const int uavs : {1, 2}) {
    for (std::uint64_t seed = 70; seed < 80; ++seed) {
      GeneratorOptions options;
      options.seed = seed;
      options.style = GeneratorStyle::kUrban;
      options.uavs = uavs;
      Scenario s = Observing(GenerateScenario(options).scenario, {"coverage"});
      s.env.step = 10;
      s.env.coverage_map = 4;
      const auto reward = MakeReward(s.env.reward);
      const auto reward_of = [&](const StepInfo& i) {
        return (*reward)(RewardInputOf(s, i.n_los, i.throughput_mbps, i.demands_met));
      };
      const auto target = [&](int refine) {
        Scenario r = s;
        r.env.coverage_refine = refine;
        AnalyticEvaluator model(r);
        const Obstacles buildings = BuildingObstacles(r.buildings);
        ModelObservations look(r, buildings);
        StepInfo info;
        Placement there = r.InitialPlacement();
        look.Fill(there, 0, 0.0, model, reward_of, info);
        there[0] = look.PointerTarget();
        return there;
      };
      const Placement cell = target(0);
      const Placement refined = target(2);
      const std::string where = std::to_string(uavs) + " UAV(s), seed " + std::to_string(seed);
      // Brute force over the window: every lattice altitude of each column within two moves.
      double best = AnalyticReward(s, cell);
      Placement want = cell;
      const Box& zone = s.uavs[0].zone;
      for (int dy = -2; dy <= 2; ++dy) {
        for (int dx = -2; dx <= 2; ++dx) {
          for (double z = s.uavs[0].initial.z -
                          s.env.step * std::floor((s.uavs[0].initial.z - zone.zmin) / s.env.step);
               z <= zone.zmax; z += s.env.step) {
            Placement p = cell;
            p[0] = {cell[0].x + dx * s.env.step, cell[0].y + dy * s.env.step, z};
            if (p[0].x < zone.xmin || p[0].x > zone.xmax || p[0].y < zone.ymin ||
                p[0].y > zone.ymax || BuildingContaining(s, p[0]) >= 0)
              continue;
            const double r = AnalyticReward(s, p);
            if (r > best) {
              best = r;
              want = p;
            }
          }
        }
      }
      EXPECT_NEAR(AnalyticReward(s, refined), best, 1e-12) << where;
      EXPECT_NEAR(refined[0].x, want[0].x, 1e-9) << where;
      EXPECT_NEAR(refined[0].y, want[0].y, 1e-9) << where;
      EXPECT_NEAR(refined[0].z, want[0].z, 1e-9) << where;
      moved += refined[0].x != cell[0].x || refined[0].y != cell[0].y ? 1 : 0;
    }
  }
  EXPECT_GT(moved, 0) << "no refinement ever left the cell's column: a weak test";
}

// With several UAVs the map's links are kept from one map to the next: after the other UAV moved,
// and after the UEs walked, the map is bit for bit the one fresh ModelObservations work out.
TEST(ModelObservations, KeptLinksGiveTheMapOfFreshModelObservationsAfterOthersMoveAndUesWalk) {
  Scenario s = GeneratedUrban(2);
  s.env.fidelity = "analytic";
  s.env.observations = {"coverage"};
  s.env.coverage_map = 4;
  const auto reward = MakeReward(s.env.reward);
  const auto reward_of = [&](const StepInfo& i) {
    return (*reward)(RewardInputOf(s, i.n_los, i.throughput_mbps, i.demands_met));
  };
  AnalyticEvaluator model(s);
  const Obstacles buildings = BuildingObstacles(s.buildings);
  ModelObservations kept(s, buildings);
  Placement placement = s.InitialPlacement();
  const auto map_of = [&](ModelObservations& look) {
    StepInfo info;
    look.Fill(placement, 0, 0.0, model, reward_of, info);
    return info.coverage;
  };
  const std::vector<double> first = map_of(kept);
  placement[1].x += s.env.step;  // the other UAV moves: UAV 0's map is worked out again
  ModelObservations fresh(s, buildings);
  const std::vector<double> after_move = map_of(kept);
  EXPECT_EQ(after_move, map_of(fresh));
  EXPECT_NE(after_move, first) << "the other UAV's move changes nothing: a weak test";
  std::vector<Vec3> walked = model.UePositions();
  for (Vec3& ue : walked)
    ue.x = s.venue.width - ue.x;  // mirrored: the UEs stand elsewhere
  model.SetUePositions(walked);
  placement[1].x -= s.env.step;
  ModelObservations fresh_again(s, buildings);
  EXPECT_EQ(map_of(kept), map_of(fresh_again)) << "links of UEs that have since walked";
}

// At packet level the model observations are the analytic model's too: the same values as at
// analytic fidelity, while the step's own metrics come from ns-3.
TEST(ModelObservations, PacketLevelComputesThemWithTheAnalyticModel) {
  Scenario s = LoadScenario(
      std::string(RLPOS_SOURCE_DIR) + "/campaigns/scenarios/b.json",
      {"env.episode_duration=0.5", "env.decision_interval=0.25", "simulation.warmup=0.5",
       "env.coverage_map=3", R"(env.observations=["coverage","lookahead"])"});
  s.env.fidelity = "packet";
  UavPositioningEnv packet(s);
  const std::vector<double> at_packet = packet.Reset(1001);
  s.env.fidelity = "analytic";
  UavPositioningEnv analytic(s);
  const std::vector<double> at_analytic = analytic.Reset(1);
  ASSERT_EQ(at_packet.size(), 2u * 9 + 3 + s.env.actions.size());
  EXPECT_EQ(at_packet, at_analytic);
}

// "best": the episode's best reward so far above the reward here (0 at a new best), scaled as the
// lookahead is; observed, it is part of the state: a placement met again after a better one is
// another moment, which it is not without the field.
TEST(BestObservation, IsTheEpisodesBestSoFarAboveHereAndPartOfTheState) {
  Scenario s = Observing(GeneratedUrban(1), {"best"});
  s.env.step = 5;  // moves that stay inside the zone, so that the one back returns
  const double bound = CoverageRewardBound(s);
  // A move from the baseline that gains, and the move back to it (actions come in opposite
  // pairs; a move clipped by the zone does not come back).
  const auto at_baseline = [&](const StepInfo& info) {
    const Vec3& p = info.positions[0];
    const Vec3& b = s.uavs[0].initial;
    return p.x == b.x && p.y == b.y && p.z == b.z;
  };
  int gain = -1;
  double start = 0.0, gained = 0.0;
  for (int a = 0; a < 6 && gain < 0; ++a) {
    UavPositioningEnv probe(s);
    probe.Reset(1);
    start = probe.RewardOf(probe.LastInfo());
    gained = probe.Step(a).reward;
    if (gained > start + 1e-9 && at_baseline(probe.Step(a % 2 == 0 ? a + 1 : a - 1).info))
      gain = a;
  }
  ASSERT_GE(gain, 0) << "no move from the baseline gains and comes back";
  const int back = gain % 2 == 0 ? gain + 1 : gain - 1;

  UavPositioningEnv env(s);
  const std::vector<double> at_start = env.Reset(1);
  ASSERT_EQ(at_start.size(), 1u);
  EXPECT_EQ(at_start[0], 0.0);
  const std::vector<std::uint64_t> start_key = env.Determining()->key;
  const StepResult up = env.Step(gain);
  EXPECT_EQ(up.observation[0], 0.0);  // a new best
  EXPECT_DOUBLE_EQ(up.info.below_best, 0.0);
  const StepResult down = env.Step(back);
  EXPECT_TRUE(at_baseline(down.info));
  EXPECT_DOUBLE_EQ(down.reward, start);
  EXPECT_DOUBLE_EQ(down.info.below_best, gained - start);
  EXPECT_DOUBLE_EQ(down.observation[0], std::min(1.0, kLookaheadGain * (gained - start) / bound));
  EXPECT_GT(down.observation[0], 0.0);
  EXPECT_NE(env.Determining()->key, start_key);

  // Without the field the same placement is the same moment again.
  Scenario without = s;
  without.env.observations = {"lookahead"};
  UavPositioningEnv plain(without);
  plain.Reset(1);
  const std::vector<std::uint64_t> plain_key = plain.Determining()->key;
  plain.Step(gain);
  plain.Step(back);
  EXPECT_EQ(plain.Determining()->key, plain_key);
}

}  // namespace
}  // namespace rlpos
