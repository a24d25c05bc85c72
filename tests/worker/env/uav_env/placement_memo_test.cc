// The analytic evaluator's memo of states per placement: revisits give the bits of a fresh
// evaluation, and the memo stays within its budget whatever the number of placements.
#include "worker/env/uav_env/placement_memo.h"

#include <gtest/gtest.h>

#include <random>

#include "tests/worker/env/uav_env/memo_walk.h"
#include "worker/env/uav_env/analytic_evaluator.h"

namespace rlpos {
namespace {

using testing::AnalyticShipped;

StepInfo MadeUpInfo(const Placement& placement, std::size_t n_ues, int salt) {
  StepInfo info;
  info.positions = placement;
  info.n_los = 0;
  info.demands_met = salt % 3;
  info.throughput_mbps = 1.5 * salt;
  for (std::size_t i = 0; i < n_ues; ++i) {
    info.snr_db.push_back(0.25 * salt + static_cast<double>(i));
    info.los.push_back(static_cast<std::uint8_t>((salt + i) % 3 == 0));
    info.n_los += info.los.back();
    info.serving.push_back(placement.size() > 1 ? static_cast<int>((i + salt) % 2) : 0);
  }
  return info;
}

void ExpectSameInfo(const StepInfo& a, const StepInfo& b) {
  ASSERT_EQ(a.positions.size(), b.positions.size());
  for (std::size_t u = 0; u < a.positions.size(); ++u) {
    EXPECT_EQ(a.positions[u].x, b.positions[u].x);
    EXPECT_EQ(a.positions[u].y, b.positions[u].y);
    EXPECT_EQ(a.positions[u].z, b.positions[u].z);
  }
  EXPECT_EQ(a.serving, b.serving);
  EXPECT_EQ(a.n_los, b.n_los);
  EXPECT_EQ(a.los, b.los);
  EXPECT_EQ(a.demands_met, b.demands_met);
  EXPECT_EQ(a.throughput_mbps, b.throughput_mbps);  // bit for bit, not within a tolerance
  EXPECT_EQ(a.snr_db, b.snr_db);
}

TEST(PlacementMemo, GivesBackWhatWasStoredForThatPlacementOnly) {
  PlacementMemo memo(2, 3);
  const Placement p{{10, 20, 30}, {40, 50, 60}};
  const StepInfo stored = MadeUpInfo(p, 3, 7);
  StepInfo found;
  EXPECT_FALSE(memo.Find(p, found));
  memo.Store(p, stored);
  ASSERT_TRUE(memo.Find(p, found));
  ExpectSameInfo(found, stored);
  EXPECT_EQ(found.active_uav, 0);
  // Another placement, the same UAVs swapped, or -0.0 for 0.0 are other keys.
  EXPECT_FALSE(memo.Find({{10, 20, 30}, {40, 50, 61}}, found));
  EXPECT_FALSE(memo.Find({{40, 50, 60}, {10, 20, 30}}, found));
  memo.Store({{0.0, 1, 1}, {5, 5, 5}}, MadeUpInfo({{0.0, 1, 1}, {5, 5, 5}}, 3, 1));
  EXPECT_FALSE(memo.Find({{-0.0, 1, 1}, {5, 5, 5}}, found));
  EXPECT_EQ(memo.Size(), 2u);
}

TEST(PlacementMemo, KeepsTheLosOfManyUes) {
  PlacementMemo memo(1, 120);  // the LoS flags take three words
  const Placement p{{1, 2, 3}};
  const StepInfo stored = MadeUpInfo(p, 120, 4);
  memo.Store(p, stored);
  StepInfo found;
  ASSERT_TRUE(memo.Find(p, found));
  ExpectSameInfo(found, stored);
}

TEST(PlacementMemo, StaysWithinItsBudgetWhateverItIsGiven) {
  PlacementMemo memo(1, 4, 4096);  // 80-byte slots: 50 of them, 37 placements
  ASSERT_EQ(memo.Capacity(), 37u);
  std::mt19937 rng(3);
  std::uniform_int_distribution<int> coordinate(0, 100);
  for (int k = 0; k < 5000; ++k) {
    const Placement p{{1.0 * coordinate(rng), 1.0 * coordinate(rng), 1.0 * coordinate(rng)}};
    const StepInfo info = MadeUpInfo(p, 4, k);
    memo.Store(p, info);
    ASSERT_LE(memo.Size(), memo.Capacity());
    StepInfo found;
    ASSERT_TRUE(memo.Find(p, found)) << k;  // the newest is always there
    ExpectSameInfo(found, info);
  }
  // A budget too small for one placement: no memo, nothing stored.
  PlacementMemo none(1, 4, 100);
  none.Store({{1, 2, 3}}, MadeUpInfo({{1, 2, 3}}, 4, 1));
  StepInfo found;
  EXPECT_FALSE(none.Find({{1, 2, 3}}, found));
}

// A random walk that comes back often: each revisit answered from the memo must carry the bits
// that scoring the placement afresh (Score on new links, which no memo answers) gives.
void ExpectRevisitsAsFresh(const Scenario& s) {
  AnalyticEvaluator walked(s), fresh(s);
  // Back where it started every 50 steps: the memo answers.
  testing::RandomWalk(s, 11, 400, 50, [&](const Placement& at) {
    const StepInfo expected = testing::FreshScore(fresh, at);
    ExpectSameInfo(walked.Evaluate(at), expected);
  });
}

TEST(PlacementMemo, RevisitsGiveTheFreshEvaluationsBitsOnOneUav) {
  ExpectRevisitsAsFresh(AnalyticShipped("b.json"));
}

TEST(PlacementMemo, RevisitsGiveTheFreshEvaluationsBitsOnSeveralUavs) {
  ExpectRevisitsAsFresh(AnalyticShipped("campus2.json"));
}

}  // namespace
}  // namespace rlpos
