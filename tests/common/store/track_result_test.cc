// A track job's result is checked before it enters the store: its settings, every metric of
// kTrackMetrics in its range, and a series that adds up to the metrics.
#include "common/store/track_result.h"

#include <gtest/gtest.h>

#include <functional>
#include <string>

namespace rlpos {
namespace {

using nlohmann::json;

// Three analytic intervals of one UAV and 4 UEs, as rlpos-sim track --json prints them.
json Result() {
  json series = json::array();
  const double rewards[] = {0.5, 0.7, 0.6};
  for (int i = 0; i < 3; ++i) {
    series.push_back({{"time", i + 1.0},
                      {"scored", true},
                      {"reward", rewards[i]},
                      {"throughput_mbps", 10.0 + i},
                      {"los_share", 0.5},
                      {"n_los", 2},
                      {"demands_met", 3},
                      {"positions", {{10.0 + i, 20.0, 30.0}}}});
  }
  return {{"scenario", "B"},
          {"positioner", "oracle-track"},
          {"fidelity", "analytic"},
          {"duration", 3.0},
          {"decision_interval", 1.0},
          {"run", 2},
          {"intervals", 3},
          {"scored_intervals", 3},
          {"n_ues", 4},
          {"mean_reward", 0.6},
          {"reward_p5", 0.51},  // (3 - 1) * 0.05 = 0.1 of the way from 0.5 to 0.6
          {"mean_throughput_mbps", 11.0},
          {"throughput_p5_mbps", 10.1},
          {"mean_delay_ms", nullptr},
          {"los_share", 0.5},
          {"los_share_p5", 0.5},
          {"outage_share", 0.25},
          {"demands_met_share_p5", 0.75},
          {"distance_flown_m", 2.0},
          {"handovers", 0.0},
          {"uavs", json::array()},
          {"series", series}};
}

std::string ErrorOf(const std::function<void(json&)>& edit) {
  json r = Result();
  edit(r);
  try {
    ParseTrackResult(r);
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "accepted";
}

TEST(TrackResult, AResultThatAddsUpIsRead) {
  const TrackRunResult r = ParseTrackResult(Result());
  EXPECT_EQ(r.positioner, "oracle-track");
  EXPECT_EQ(r.run, 2u);
  EXPECT_EQ(r.scored_intervals, 3);
  EXPECT_DOUBLE_EQ(r.metrics.mean_reward, 0.6);
  EXPECT_TRUE(std::isnan(r.metrics.mean_delay_ms));
  ASSERT_EQ(r.intervals.size(), 3u);
  EXPECT_DOUBLE_EQ(r.intervals[2].los_share, 0.5);
  EXPECT_DOUBLE_EQ(r.intervals[2].demands_met_share, 0.75);
  EXPECT_EQ(r.intervals[2].positions.front().x, 12.0);
}

TEST(TrackResult, WhatDoesNotAddUpOrFitIsRefused) {
  EXPECT_EQ(ErrorOf([](json& r) { r["mean_reward"] = 0.7; }),
            "result \"mean_reward\" or \"reward_p5\" does not add up from the series");
  EXPECT_EQ(ErrorOf([](json& r) { r["reward_p5"] = 0.5; }),
            "result \"mean_reward\" or \"reward_p5\" does not add up from the series");
  EXPECT_EQ(ErrorOf([](json& r) { r["series"][1]["scored"] = false; }),
            "result \"scored_intervals\" is not the number of scored intervals in the series");
  EXPECT_EQ(ErrorOf([](json& r) { r["series"][2]["time"] = 2.0; }),
            "result \"series/2/time\" does not come after the interval before");
  EXPECT_EQ(ErrorOf([](json& r) {
              r["series"][1]["positions"].push_back({1, 2, 3});
            }),
            "result \"series/1/positions\" has another number of UAVs");
  EXPECT_EQ(ErrorOf([](json& r) {
              r["series"][0]["n_los"] = 5;
            }).rfind("result \"series/0/n_los\" is not a number in", 0),
            0u);
  EXPECT_EQ(ErrorOf([](json& r) { r["los_share"] = 1.5; }),
            "result \"los_share\" is not a number in [0, 1]");
  EXPECT_EQ(ErrorOf([](json& r) {
              r["mean_reward"] = nullptr;
            }).rfind("result \"mean_reward\" is not a number in", 0),
            0u);
  EXPECT_EQ(ErrorOf([](json& r) { r.erase("handovers"); }), "result has no \"handovers\"");
  EXPECT_EQ(ErrorOf([](json& r) { r["positioner"] = "teleport"; }),
            "result \"positioner\" is not a known name");
  EXPECT_EQ(ErrorOf([](json& r) { r["intervals"] = 4; }),
            "result \"series\" does not list the run's 4 intervals");
  EXPECT_EQ(ErrorOf([](json& r) {
              r["intervals"] = 601;
            }).rfind("result \"intervals\" is not an integer in 1..600", 0),
            0u);
  EXPECT_EQ(ErrorOf([](json& r) { r["series"][0]["positions"][0][1] = "x"; }),
            "result \"series/0/positions\" holds a coordinate that is not a finite number");
  EXPECT_EQ(ErrorOf([](json& r) { r = json::array(); }), "result is not a JSON object");
}

}  // namespace
}  // namespace rlpos
