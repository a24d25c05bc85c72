// Scoring placements that move one UAV with the others' part worked out once gives, field by
// field and bit for bit, what AnalyticEvaluator::Score gives: with UAVs on channels of their own,
// with two sharing one, with UEs tied to a UAV, and where the moving UAV ties another's SNR; with
// each point's shares remembered (PointShares) and without.
#include "worker/env/uav_env/one_uav_moves.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "common/scenario/scenario_checks.h"
#include "common/scenario_generator/scenario_generator.h"
#include "worker/env/uav_env/analytic_evaluator.h"

namespace rlpos {
namespace {

Scenario GeneratedUrban(int uavs) {
  GeneratorOptions options;
  options.seed = 31;
  options.style = GeneratorStyle::kUrban;
  options.uavs = uavs;
  Scenario s = GenerateScenario(options).scenario;
  s.env.fidelity = "analytic";
  return s;
}

void ExpectSame(const StepInfo& got, const StepInfo& want, const std::string& where) {
  ASSERT_EQ(got.positions.size(), want.positions.size()) << where;
  for (std::size_t u = 0; u < got.positions.size(); ++u) {
    EXPECT_EQ(got.positions[u].x, want.positions[u].x) << where;
    EXPECT_EQ(got.positions[u].y, want.positions[u].y) << where;
    EXPECT_EQ(got.positions[u].z, want.positions[u].z) << where;
  }
  EXPECT_EQ(got.serving, want.serving) << where;
  EXPECT_EQ(got.active_uav, want.active_uav) << where;
  EXPECT_EQ(got.n_los, want.n_los) << where;
  EXPECT_EQ(got.los, want.los) << where;
  EXPECT_EQ(got.snr_db, want.snr_db) << where;
  EXPECT_EQ(got.demands_met, want.demands_met) << where;
  EXPECT_EQ(got.throughput_mbps, want.throughput_mbps) << where;  // the bits
  EXPECT_TRUE(got.coverage.empty() && got.lookahead.empty()) << where;
}

// Every UAV in turn moves over a grid of its zone and onto each other UAV (an SNR tie), scored
// both ways, the others where they start and then with the next UAV moved to its zone's middle
// (as a coverage map is made again after another UAV moved, each point keeping what it
// remembered); returns how many points had a UE change UAV (so the sweep exercised association).
int SweepEachUav(const Scenario& s) {
  AnalyticEvaluator model(s);
  AnalyticEvaluator fresh(s);  // Score from scratch: no memo of shares shared with `model`
  const Placement start = s.InitialPlacement();
  const StepInfo at_start = fresh.Evaluate(start);
  int reassigned = 0;
  for (std::size_t active = 0; active < start.size(); ++active) {
    std::vector<Vec3> points;
    const Box& zone = s.uavs[active].zone;
    for (int i = 0; i <= 6; ++i) {
      for (int j = 0; j <= 6; ++j) {
        points.push_back({zone.xmin + (zone.xmax - zone.xmin) * i / 6.0,
                          zone.ymin + (zone.ymax - zone.ymin) * j / 6.0,
                          zone.zmin + (zone.zmax - zone.zmin) * ((i + j) % 4) / 3.0});
      }
    }
    for (std::size_t u = 0; u < start.size(); ++u)
      points.push_back(start[u]);
    std::vector<Placement> arrangements{start};
    if (start.size() > 1) {
      Placement moved = start;
      const std::size_t next = (active + 1) % start.size();
      const Box& z = s.uavs[next].zone;
      moved[next] = {(z.xmin + z.xmax) / 2, (z.ymin + z.ymax) / 2, z.zmax};
      arrangements.push_back(moved);
    }
    // Each point's remembered shares, kept from one arrangement to the next as the coverage map
    // keeps them (its links do not change).
    std::vector<PointShares> remembered(points.size());
    StepInfo info;  // reused, as the coverage map does
    for (const Placement& placement : arrangements) {
      std::vector<std::vector<UeLink>> others(placement.size());
      std::vector<const std::vector<UeLink>*> links(placement.size(), nullptr);
      for (std::size_t u = 0; u < placement.size(); ++u) {
        if (u != active) {
          others[u] = model.LinksAt(u, placement[u]);
          links[u] = &others[u];
        }
      }
      OneUavMoves moves(model, placement, active, links);
      // Without remembering, then remembering twice. Each pass takes the other channels from
      // the kept shares.
      for (int pass = 0; pass < 3; ++pass) {
        for (std::size_t k = 0; k < points.size(); ++k) {
          const Vec3& p = points[k];
          if (BuildingContaining(s, p) >= 0)
            continue;
          const std::vector<UeLink> mine = model.LinksAt(active, p);
          moves.ScoreInto(p, mine, info, pass == 0 ? nullptr : &remembered[k]);
          Placement probe = placement;
          probe[active] = p;
          std::vector<std::vector<UeLink>> all(placement.size());
          std::vector<const std::vector<UeLink>*> views;
          for (std::size_t u = 0; u < placement.size(); ++u) {
            all[u] = fresh.LinksAt(u, probe[u]);
            views.push_back(&all[u]);
          }
          const std::string where = "pass " + std::to_string(pass) + ", UAV " +
                                    std::to_string(active) + " at " + std::to_string(p.x) + "," +
                                    std::to_string(p.y) + "," + std::to_string(p.z);
          ExpectSame(info, fresh.Score(probe, views), where);
          if (info.serving != at_start.serving)
            ++reassigned;
        }
      }
    }
  }
  return reassigned;
}

TEST(OneUavMoves, ScoresAsScoreDoesWithUavsOnChannelsOfTheirOwn) {
  const Scenario s = GeneratedUrban(4);
  ASSERT_EQ(s.uavs.size(), 4u);
  EXPECT_GT(SweepEachUav(s), 20);
}

TEST(OneUavMoves, ScoresAsScoreDoesWithTwoUavsOnOneChannelAndUesTiedToAUav) {
  Scenario s = GeneratedUrban(3);
  ASSERT_EQ(s.uavs.size(), 3u);
  ASSERT_GE(s.ues.size(), 4u);
  s.uavs[2].channel = s.uavs[0].channel;
  s.ues[0].uav = s.uavs[0].name;
  s.ues[3].uav = s.uavs[1].name;
  EXPECT_GT(SweepEachUav(s), 20);
}

TEST(OneUavMoves, ScoresAsScoreDoesWithOneUav) {
  const Scenario s = GeneratedUrban(1);
  ASSERT_EQ(s.uavs.size(), 1u);
  SweepEachUav(s);
}

}  // namespace
}  // namespace rlpos
