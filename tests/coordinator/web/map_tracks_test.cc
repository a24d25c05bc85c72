// The track runs a scenario's map plays: each positioner's first run, its UAVs where the store
// has them, and the UEs where the mobility code walks them for that RngRun at each interval end.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>

#include "common/mobility/ue_trajectories.h"
#include "common/scenario/scenario_parser.h"
#include "common/store/sqlite_db.h"
#include "common/store/track_rows.h"
#include "coordinator/scheduling/coordinator_store.h"
#include "coordinator/web/map_views.h"
#include "tests/support/campaign_fixtures.h"

namespace rlpos::web {
namespace {

using nlohmann::json;
using rlpos::testing::SourcePath;

// Longer than the street's simulation.duration (10 s) and env.episode_duration (set to 4 s): the
// UEs walk on only when the trajectories are drawn for the run's duration, as the track job does.
constexpr double kDuration = 16.0, kInterval = 2.0;
constexpr int kFrames = 8;
const std::vector<std::string> kSet{"env.decision_interval=2", "env.episode_duration=4"};

// The street of campaigns/mobility.json (ten pedestrians, gauss_markov), RngRuns 3 and 4.
json WalkCampaign() {
  return {{"name", "walk-map"},
          {"scenarios",
           {{{"file", SourcePath("campaigns/scenarios/mobility-street.json")}, {"set", kSet}}}},
          {"rng_runs", {3, 4}},
          {"positioners", json::array()},
          {"track", {{"positioners", {"oracle-track", "centroid"}}, {"duration", kDuration}}}};
}

double Apart(const Vec3& a, const Vec3& b) {
  return std::hypot(a.x - b.x, a.y - b.y);
}

// The UAV's position stored at the end of interval i of a run: distinct per positioner and run.
Vec3 StoredUav(double base, int i) {
  return {base + 1.5 * i, 40.26 + i, 30.0};
}

TrackRunResult StoredRun(const std::string& positioner, std::uint64_t rng_run, double base) {
  TrackRunResult run;
  run.positioner = positioner;
  run.fidelity = "analytic";
  run.run = rng_run;
  run.duration_s = kDuration;
  run.decision_interval_s = kInterval;
  for (int i = 0; i < kFrames; ++i) {
    TrackIntervalRow row;
    row.time_s = kInterval * (i + 1);
    row.reward = 0.5;
    row.positions = {StoredUav(base, i)};
    run.intervals.push_back(row);
  }
  run.scored_intervals = kFrames;
  return run;
}

// What the track job of RngRun `run` walks: the scenario at that run, up to the duration.
std::vector<UeTrajectory> Walks(std::int64_t run) {
  std::ifstream in(SourcePath("campaigns/scenarios/mobility-street.json"));
  json document = json::parse(in);
  std::vector<std::string> set = kSet;
  set.push_back("simulation.run=" + std::to_string(run));
  ApplyOverrides(document, set);
  Scenario s = ParseScenario(document);
  s.simulation.duration = kDuration;
  return UeTrajectories(s);
}

class MapTracksTest : public ::testing::Test {
 protected:
  MapTracksTest() : store_(dir_.File("rlpos.db")) {
    campaign_ = ExpandCampaign(ParseCampaign(WalkCampaign(), "/"));
    campaign_.use_cache = false;
    store_.ledger.Submit(campaign_);
  }

  void Insert(const std::string& positioner, std::int64_t rng_run, double base) {
    const Job& job = rlpos::testing::FindJob(
        campaign_, "track/street/" + positioner + "/run" + std::to_string(rng_run));
    InsertTrackRun(store_.db.sql(), {job.id, campaign_.id, "street", positioner, rng_run},
                   StoredRun(positioner, static_cast<std::uint64_t>(rng_run), base));
    store_.db.sql().Exec("UPDATE jobs SET state = 'succeeded' WHERE id = '" + job.id + "'");
  }

  json Street() {
    const auto maps = ScenarioMapsJson(store_.reader, campaign_.id);
    EXPECT_TRUE(maps.has_value());
    EXPECT_EQ((*maps)["scenarios"].size(), 1u);
    return (*maps)["scenarios"][0];
  }

  rlpos::testing::TempDir dir_;
  CoordinatorStore store_;
  ExpandedCampaign campaign_;
};

TEST_F(MapTracksTest, NoTrackRunNoTracks) {
  EXPECT_FALSE(Street().contains("tracks"));
}

TEST_F(MapTracksTest, FramesOfEachPositionersFirstRunWithItsUavsAndTheWalkingUes) {
  Insert("oracle-track", 4, 60.0);
  Insert("oracle-track", 3, 20.0);  // its first run: the one played
  Insert("centroid", 4, 80.0);      // its only run: a second run on the map
  const json tracks = Street()["tracks"];

  ASSERT_EQ(tracks["positioners"].size(), 2u) << tracks.dump();
  const json& centroid = tracks["positioners"][0];  // report order: held placements first
  const json& oracle = tracks["positioners"][1];
  EXPECT_EQ(centroid["positioner"], "centroid");
  EXPECT_EQ(centroid["rng_run"], 4);
  EXPECT_EQ(oracle["positioner"], "oracle-track");
  EXPECT_EQ(oracle["rng_run"], 3);
  for (const auto& [p, base] : {std::pair<const json*, double>{&centroid, 80.0}, {&oracle, 20.0}}) {
    const json& frames = (*p)["uavs"];
    ASSERT_EQ(frames.size(), static_cast<std::size_t>(kFrames));
    for (int i = 0; i < kFrames; ++i) {
      const Vec3 stored = StoredUav(base, i);
      ASSERT_EQ(frames[i].size(), 1u);  // one UAV
      EXPECT_DOUBLE_EQ(frames[i][0][0].get<double>(), stored.x);
      EXPECT_DOUBLE_EQ(frames[i][0][1].get<double>(), std::round(stored.y * 10) / 10);  // 0.1 m
      EXPECT_DOUBLE_EQ(frames[i][0][2].get<double>(), stored.z);
    }
  }

  ASSERT_EQ(tracks["runs"].size(), 2u);
  bool moved = false, moved_late = false, runs_differ = false;
  for (std::size_t r = 0; r < 2; ++r) {
    const json& run = tracks["runs"][r];
    const std::int64_t rng_run = 3 + static_cast<std::int64_t>(r);  // by RngRun
    EXPECT_EQ(run["rng_run"], rng_run);
    EXPECT_EQ(run["duration"], kDuration);
    EXPECT_EQ(run["times"], json({2.0, 4.0, 6.0, 8.0, 10.0, 12.0, 14.0, 16.0}));
    const auto walks = Walks(rng_run);
    const auto other = Walks(7 - rng_run);
    ASSERT_EQ(run["ues"].size(), static_cast<std::size_t>(kFrames));
    for (std::size_t i = 0; i < kFrames; ++i) {
      const double t = kInterval * static_cast<double>(i + 1);
      const json& frame = run["ues"][i];
      ASSERT_EQ(frame.size(), walks.size());
      for (std::size_t u = 0; u < walks.size(); ++u) {
        const Vec3 at = walks[u].PositionAt(t);
        EXPECT_NEAR(frame[u][0].get<double>(), at.x, 0.05 + 1e-9) << "UE " << u << " at " << t;
        EXPECT_NEAR(frame[u][1].get<double>(), at.y, 0.05 + 1e-9) << "UE " << u << " at " << t;
        moved = moved || Apart(at, walks[u].PositionAt(0.0)) > 1.0;
        moved_late = moved_late || Apart(at, walks[u].PositionAt(10.0)) > 1.0;
        runs_differ = runs_differ || Apart(at, other[u].PositionAt(t)) > 1.0;
      }
    }
  }
  EXPECT_TRUE(moved) << "the street's UEs walk";
  EXPECT_TRUE(moved_late) << "and walk on past the scenario's own duration";
  EXPECT_TRUE(runs_differ) << "each RngRun walks its own way";
}

}  // namespace
}  // namespace rlpos::web
