// The memo of analytic states shared by the envs of one scenario: evaluators on several threads
// at once get the bits a fresh evaluation gives, share what each stored, and stay within budget.
#include "worker/env/uav_env/shared_placement_memo.h"

#include <gtest/gtest.h>

#include <random>
#include <set>
#include <thread>
#include <tuple>

#include "tests/worker/env/uav_env/memo_walk.h"
#include "worker/env/uav_env/analytic_evaluator.h"

namespace rlpos {
namespace {

using testing::AnalyticShipped;

// Whether two states are the same bits (no tolerance); gtest's macros are not for threads.
bool SameInfo(const StepInfo& a, const StepInfo& b) {
  if (a.positions.size() != b.positions.size())
    return false;
  for (std::size_t u = 0; u < a.positions.size(); ++u) {
    if (std::tie(a.positions[u].x, a.positions[u].y, a.positions[u].z) !=
        std::tie(b.positions[u].x, b.positions[u].y, b.positions[u].z)) {
      return false;
    }
  }
  return a.serving == b.serving && a.n_los == b.n_los && a.los == b.los &&
         a.demands_met == b.demands_met && a.throughput_mbps == b.throughput_mbps &&
         a.snr_db == b.snr_db;
}

using Key = std::vector<std::tuple<double, double, double>>;
Key KeyOf(const Placement& p) {
  Key key;
  for (const Vec3& v : p)
    key.emplace_back(v.x, v.y, v.z);
  return key;
}

// `threads` evaluators sharing one memo walk the lattice at once (each its own random walk, all
// from the start, so they meet often); every state each gets must be a fresh evaluation's bits.
// Returns the placements visited.
std::set<Key> WalkTogether(const Scenario& s, SharedPlacementMemo& memo, int threads, int steps) {
  std::vector<std::set<Key>> visited(threads);
  std::vector<int> mismatches(threads, 0);
  std::vector<std::thread> pool;
  for (int t = 0; t < threads; ++t) {
    pool.emplace_back([&, t] {
      AnalyticEvaluator walked(s, std::shared_ptr<SharedPlacementMemo>(&memo, [](auto*) {}));
      AnalyticEvaluator fresh(s);
      testing::RandomWalk(s, 100 + t, steps, 40, [&](const Placement& at) {
        const StepInfo expected = testing::FreshScore(fresh, at);
        if (!SameInfo(walked.Evaluate(at), expected))
          ++mismatches[t];
        visited[t].insert(KeyOf(at));
      });
    });
  }
  for (auto& th : pool)
    th.join();
  std::set<Key> all;
  for (int t = 0; t < threads; ++t) {
    EXPECT_EQ(mismatches[t], 0) << "thread " << t;
    all.insert(visited[t].begin(), visited[t].end());
  }
  return all;
}

void ExpectSharedHitsAsFresh(const Scenario& s) {
  SharedPlacementMemo memo(s.uavs.size(), s.ues.size(), SharedPlacementMemo::kMaxBudgetBytes);
  const std::set<Key> visited = WalkTogether(s, memo, 4, 300);
  ASSERT_LT(visited.size(), memo.Capacity());  // nothing was dropped
  // One entry per placement, whoever visited it first: the evaluators shared what they stored.
  EXPECT_EQ(memo.Size(), visited.size());
  // Each placement is found by a later evaluator, which evaluates nothing (a fresh state's bits).
  AnalyticEvaluator later(s, std::shared_ptr<SharedPlacementMemo>(&memo, [](auto*) {}));
  for (const Key& key : visited) {
    Placement p;
    for (const auto& [x, y, z] : key)
      p.push_back({x, y, z});
    StepInfo found;
    ASSERT_TRUE(memo.Find(p, found));
    EXPECT_TRUE(SameInfo(later.Evaluate(p), found));
  }
}

TEST(SharedPlacementMemo, HitsFromSeveralThreadsGiveTheFreshBitsOnOneUav) {
  ExpectSharedHitsAsFresh(AnalyticShipped("b.json"));
}

TEST(SharedPlacementMemo, HitsFromSeveralThreadsGiveTheFreshBitsOnSeveralUavs) {
  ExpectSharedHitsAsFresh(AnalyticShipped("campus2.json"));
}

TEST(SharedPlacementMemo, StaysWithinItsBudgetWhateverItIsGiven) {
  // One env's budget for one env, a few MiB however many envs share it.
  EXPECT_EQ(SharedPlacementMemo::BudgetFor(1), PlacementMemo::kDefaultBudgetBytes);
  EXPECT_EQ(SharedPlacementMemo::BudgetFor(256), SharedPlacementMemo::kMaxBudgetBytes);
  EXPECT_EQ(SharedPlacementMemo::BudgetFor(4096), SharedPlacementMemo::kMaxBudgetBytes);

  const std::size_t budget = 64 * 1024;  // 16 shards of 4 KiB: 50 slots, 37 placements each
  SharedPlacementMemo memo(1, 4, budget);
  ASSERT_EQ(memo.Capacity(), SharedPlacementMemo::kShards * 37);
  std::vector<std::thread> pool;
  std::vector<int> lost(4, 0);
  for (int t = 0; t < 4; ++t) {
    pool.emplace_back([&, t] {
      std::mt19937 rng(t);
      std::uniform_int_distribution<int> coordinate(0, 1000);
      for (int k = 0; k < 20000; ++k) {
        const Placement p{{1.0 * coordinate(rng), 1.0 * coordinate(rng), 1.0 * t}};
        StepInfo info;
        info.positions = p;
        info.throughput_mbps = k;
        info.snr_db.assign(4, 1.0 * k);
        info.los.assign(4, 1);
        info.n_los = 4;
        info.serving.assign(4, 0);
        memo.Store(p, info);
        StepInfo found;
        // The newest is there unless another thread filled its shard since (then it is gone,
        // not wrong).
        if (memo.Find(p, found) && found.throughput_mbps != k)
          ++lost[t];
        if (memo.Size() > memo.Capacity())
          ++lost[t];
      }
    });
  }
  for (auto& th : pool)
    th.join();
  for (int t = 0; t < 4; ++t)
    EXPECT_EQ(lost[t], 0) << "thread " << t;
  EXPECT_LE(memo.Size(), memo.Capacity());
}

}  // namespace
}  // namespace rlpos
